package rtd.io;

import java.util.List;

/**
 * One group {@code :(…)} of a statement of the {@link Grammar}: what it means in messages, how it is written,
 * and the rule its values follow, which {@link StatementValues#check} applies as soon as the group is read
 * (section 4.1; Part II, "The scene file"; Part III).
 *
 * @param shape how it is written, for "write it as …": {@code x|y|z}, {@code path}
 * @param size  how many numbers it holds; 1 for a word or properties
 * @param help  the help when a direction ({@link Rule#DIRECTION}, {@link Rule#VIEW}) is zero
 */
record Group(String meaning, Rule rule, String shape, int size, String help) {

    /** The keys of a material's properties, in the order of {@link rtd.geometry.Material}'s fields. */
    static final List<String> KEYS = List.of("ambient", "diffuse", "specular", "shininess", "reflective",
            "transparency", "ior");

    /** What a group holds, and the rule its values follow; every number is finite. */
    enum Rule {
        NUMBERS,
        /** One number greater than 0: a radius, a zoom, a scale. */
        POSITIVE,
        /** One number at least 0: a cone's radius. */
        AT_LEAST_ZERO,
        /** A camera's field of view, between 0 and 180 degrees. */
        ANGLE,
        /** An area light's samples along its edges: whole numbers from 1 to {@link rtd.scene.AreaLight#MOST_SAMPLES}. */
        SAMPLES,
        /** Three channels, each a whole number from 0 to 255; an expression is rounded ½ up (Part III). */
        COLOUR,
        /** An object's colour, or the name of its pattern (Part III, "Patterns"). */
        PAINT,
        /** Not zero, and neither too short nor too long for float to normalise. */
        DIRECTION,
        /** A camera's view: a direction, or {@code (at x|y|z)}, a point to look at (Part III). */
        VIEW,
        /** One name of letters, digits, {@code _} and {@code -}. */
        NAME,
        /** One file path, everything up to the group's {@code )}, blanks around it trimmed. */
        PATH,
        /** {@code key=number} pairs of {@link #KEYS}, each at least 0 (ior at least 1), each key at most once. */
        PROPERTIES,
        /** A word, a blank and numbers separated by {@code |}: {@code scale 2}, {@code translate 0|1|0}. */
        STEP
    }

    /** A group of numbers written as {@code shape}, such as {@code x|y|z}; their count is the shape's. */
    static Group numbers(String meaning, Rule rule, String shape, String help) {
        return new Group(meaning, rule, shape, shape.split("\\|").length, help);
    }

    static Group numbers(String meaning, Rule rule, String shape) {
        return numbers(meaning, rule, shape, null);
    }

    static Group numbers(String meaning, String shape) {
        return numbers(meaning, Rule.NUMBERS, shape, null);
    }

    /** A group that holds one word (a name, a path, a step) or properties, written as {@code shape}. */
    static Group word(String meaning, Rule rule, String shape) {
        return new Group(meaning, rule, shape, 1, null);
    }

    /** What the group holds, for messages: "3 numbers (x|y|z)", "a name". */
    String contents() {
        return switch (rule) {
            case NAME -> "a name";
            case PATH -> "a file path";
            case PROPERTIES -> "key=value pairs";
            case STEP -> "an operation such as (" + shape + ")";
            default -> size == 1 ? "1 number (" + shape + ")" : size + " numbers (" + shape + ")";
        };
    }

    /** "the centre of 'sphere'", for messages. */
    String of(Statement statement) {
        return "the " + meaning + " of '" + statement.keyword() + "'";
    }
}
