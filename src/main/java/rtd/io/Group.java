package rtd.io;

import java.util.List;

/**
 * One group {@code :(…)} of a statement of the {@link Grammar}: what it means in messages and what it holds
 * (numbers in the paper; a name, a path or a material's {@code key=value} pairs in Part II).
 *
 * @param meaning what the group is, for messages: "centre", "view direction"
 * @param shape   how it is written, for "write it as …": {@code x|y|z}, {@code path}
 * @param size    how many numbers a {@link Kind#NUMBERS} group holds; 1 for the others
 * @param keys    the keys a {@link Kind#PROPERTIES} group may hold; empty for the others
 * @param orAt    whether it may be written {@code (at x|y|z)}, a point to look at (Part III)
 * @param orName  whether it may hold one name instead of its numbers: an object's colour group, naming a pattern
 */
record Group(String meaning, Kind kind, String shape, int size, List<String> keys, boolean orAt, boolean orName) {

    enum Kind {
        /** A fixed count of numbers separated by {@code |}. */
        NUMBERS,
        /** One name of letters, digits, {@code _} and {@code -}, such as a material's. */
        NAME,
        /** One file path, everything up to the group's {@code )}, blanks around it trimmed. */
        PATH,
        /** {@code key=number} pairs separated by {@code |}, each key at most once, any left out. */
        PROPERTIES,
        /** A word, a blank and numbers separated by {@code |}, as many as the word takes: {@code scale 2}, {@code translate 0|1|0}. */
        OPERATION
    }

    /** A group of numbers written as {@code shape}, such as {@code x|y|z}; their count is the shape's. */
    static Group numbers(String meaning, String shape) {
        return new Group(meaning, Kind.NUMBERS, shape, shape.split("\\|").length, List.of(), false, false);
    }

    /** A camera's view direction {@code (x|y|z)}, or {@code (at x|y|z)}: the point it looks at. */
    static Group view(String meaning) {
        return new Group(meaning, Kind.NUMBERS, "x|y|z", 3, List.of(), true, false);
    }

    /** A group that holds one name, one path or one step ({@link Kind#OPERATION}), written as {@code shape}. */
    static Group word(String meaning, Kind kind, String shape) {
        return new Group(meaning, kind, shape, 1, List.of(), false, false);
    }

    static Group name(String meaning, String shape) {
        return word(meaning, Kind.NAME, shape);
    }

    static Group properties(String meaning, String... keys) {
        return new Group(meaning, Kind.PROPERTIES, "key=value|key=value...", 1, List.of(keys), false, false);
    }

    /** This group, which may hold a pattern's name if it is an object's colour (Part III, "Patterns"). */
    Group orPatternName() {
        return meaning.equals("colour") && kind == Kind.NUMBERS ? new Group(meaning, kind, shape, size, keys, orAt, true) : this;
    }

    /** What the group holds, for messages: "3 numbers (x|y|z)", "a name". */
    String contents() {
        return switch (kind) {
            case NUMBERS -> size == 1 ? "1 number (" + shape + ")" : size + " numbers (" + shape + ")";
            case NAME -> "a name";
            case PATH -> "a file path";
            case PROPERTIES -> "key=value pairs";
            case OPERATION -> "an operation such as (" + shape + ")";
        };
    }

    /** "the centre of 'sphere'", for messages. */
    String of(Statement statement) {
        return "the " + meaning + " of '" + statement.keyword() + "'";
    }
}
