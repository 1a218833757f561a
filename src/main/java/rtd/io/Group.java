package rtd.io;

import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import rtd.math.Vector3f;
import rtd.scene.AreaLight;

/**
 * One group {@code :(…)} of a statement of the {@link Grammar}: its meaning in messages, its {@code shape}
 * ({@code x|y|z}), its {@code size} (1 for a word or properties), the rule its values follow (section 4.1; Part
 * II, "The scene file"; Part III) and the {@code help} for a zero direction.
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
        /** An area light's samples along its edges: whole numbers from 1 to {@link AreaLight#MOST_SAMPLES}. */
        SAMPLES,
        /** Three channels, each a whole number from 0 to 255; an expression is rounded ½ up (Part III). */
        COLOUR,
        /** An object's colour, or the name of its pattern (Part III, "Patterns"). */
        PAINT,
        /** Three numbers that float can normalise: not zero, not too short or too long. */
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
    static Group numbers(String meaning, Rule rule, String shape) {
        return new Group(meaning, rule, shape, shape.split("\\|").length, null);
    }

    static Group numbers(String meaning, String shape) {
        return numbers(meaning, Rule.NUMBERS, shape);
    }

    /** A group that holds one word (a name, a path, a step) or properties, written as {@code shape}. */
    static Group word(String meaning, Rule rule, String shape) {
        return new Group(meaning, rule, shape, 1, null);
    }

    /** For messages: "3 numbers (x|y|z)", "a name". */
    String contents() {
        return switch (rule) {
            case NAME -> "a name";
            case PATH -> "a file path";
            case PROPERTIES -> "key=value pairs";
            case STEP -> "an operation such as (" + shape + ")";
            default -> size == 1 ? "1 number (" + shape + ")" : size + " numbers (" + shape + ")";
        };
    }

    /** Whether the group's numbers are whole ones only: a colour's channels, an area light's samples. */
    boolean takesWholeNumbers() {
        return rule == Rule.COLOUR || rule == Rule.PAINT || rule == Rule.SAMPLES;
    }

    /** "the centre of 'sphere'", for messages. */
    String of(Statement statement) {
        return "the " + meaning + " of '" + statement.keyword() + "'";
    }

    /** Checks group {@code g} of {@code v} by this rule: an error at the first value that breaks it. */
    void check(StatementValues v, int g) throws SceneException {
        switch (rule) {
            case NAME, PATH -> { }
            case COLOUR, PAINT -> {
                for (int k = 0; k < 3 && g != v.patternGroup; k++) {
                    channel(v, g, k);
                }
            }
            case PROPERTIES -> {
                for (int k = 0; k < v.size(g); k++) {
                    float minimum = v.key(g, k) == KEYS.size() - 1 ? 1 : 0; // the ior
                    if (finite(v, g, k) < minimum) {
                        throw must(v, g, k, numberName(v, g, k), "at least " + plain(minimum), minimum > 0
                                ? "an index of refraction is 1 for air, 1.33 for water, 1.5 for glass"
                                : "0 turns this part of the finish off");
                    }
                }
            }
            default -> {
                for (int k = rule == Rule.STEP ? 1 : 0; k < v.size(g); k++) { // a step's word, then its numbers
                    finite(v, g, k);
                }
                checkNumbers(v, g, v.number(g, 0));
            }
        }
    }

    private void checkNumbers(StatementValues v, int g, float value) throws SceneException {
        switch (rule) {
            case POSITIVE -> {
                if (!(value > 0)) {
                    throw must(v, g, 0, meaning, "greater than 0", v.tree(g, 0) != null
                            ? "an expression here must be greater than 0 at every clock the scene is drawn at"
                            : value < 0 ? "without its minus sign: " + plain(-value)
                            : "a " + meaning + " of 0 leaves nothing to see; give a number greater than 0, such as 1");
                }
            }
            case AT_LEAST_ZERO -> {
                if (value < 0) {
                    String written = v.written(g, 0);
                    throw must(v, g, 0, meaning, "at least 0", "without its minus sign: " + written.substring(1));
                }
            }
            case ANGLE -> {
                if (!(value > 0 && value < 180)) {
                    throw must(v, g, 0, meaning, "greater than 0 and less than 180 degrees",
                            "it is the angle the picture's width spans, such as 60");
                }
            }
            case SAMPLES -> {
                for (int k = 0; k < 2; k++) {
                    float n = v.number(g, k);
                    if (!(n >= 1 && n <= AreaLight.MOST_SAMPLES && n == Math.rint(n))) {
                        throw must(v, g, k, "number of samples along the " + (k == 0 ? "first" : "second") + " edge",
                                "a whole number from 1 to " + AreaLight.MOST_SAMPLES,
                                "more samples make a softer shadow and cost more shadow rays; 4|4 is a good start");
                    }
                }
            }
            case VIEW, DIRECTION -> direction(v, g);
            default -> { }
        }
    }

    private float finite(StatementValues v, int g, int k) throws SceneException {
        float value = v.number(g, k);
        if (Float.isFinite(value)) {
            return value;
        }
        String written = v.written(g, k);
        boolean overflow = Hints.tooLarge(written);
        throw v.errorAtValue(g, k, "the " + numberName(v, g, k) + " must be a finite number, found " + written
                + (overflow ? ", which is too large for a float" : ""), overflow ? Hints.FLOAT_RANGE
                        : "NaN (not a number) and Infinity are not numbers a scene can use; give a finite number");
    }

    /** What number {@code k} is, for messages: "x of the centre", "radius", "value of 'ior'". */
    private String numberName(StatementValues v, int g, int k) {
        return rule == Rule.PROPERTIES ? "value of '" + KEYS.get(v.key(g, k)) + "'"
                : size == 3 ? "xyz".charAt(k) + " of the " + meaning : meaning;
    }

    /** Channel {@code k} of a colour: a whole number from 0 to 255, an expression once rounded. */
    private static void channel(StatementValues v, int g, int k) throws SceneException {
        float value = v.channel(g, k);
        if (value >= 0 && value <= 255 && value == Math.rint(value)) {
            return; // an expression's channel is rounded already: only out of range is it wrong
        }
        String name = (k == 0 ? "red" : k == 1 ? "green" : "blue") + " channel";
        if (v.tree(g, k) != null) {
            throw must(v, g, k, name, "from 0 to 255",
                    "an expression in a colour is rounded to a whole number, which must be from 0 to 255");
        }
        String fractions = Hints.colourFractions(v.numbers(g));
        throw must(v, g, k, name, "a whole number from 0 to 255", fractions != null ? fractions
                : "each channel runs from 0 (none of that colour) to 255 (all of it), in whole numbers");
    }

    /** A direction, or a point to look at from the camera's position in group 0: one float can normalise. */
    private void direction(StatementValues v, int g) throws SceneException {
        boolean target = v.target == g;
        Vector3f from = v.vector(0);
        String why = unusable(target ? v.vector(g).subtract(from) : v.vector(g));
        String text = IntStream.range(0, 3).mapToObj(k -> v.written(g, k))
                .collect(Collectors.joining("|", target ? "(at " : "(", ")"));
        if ("zero".equals(why) && target) {
            throw v.errorAtValue(g, 0, "the camera cannot look at its own position " + text, "give a point in front of "
                    + "the camera: (at " + plain(from.x()) + "|" + plain(from.y()) + "|" + plain(from.z() - 1)
                    + ") looks along -z");
        }
        if ("zero".equals(why)) {
            throw v.errorAtValue(g, 0, "the " + meaning + " must not be zero, found " + text, help);
        }
        if (why != null && target) {
            throw v.errorAtValue(g, 0, "the point " + text + " is too " + ("long".equals(why) ? "far from" : "near")
                    + " the camera's position to compute the view direction in float",
                    "give a point at a distance near 1 to 1000 from the camera");
        }
        if (why != null) {
            throw v.errorAtValue(g, 0, "the " + meaning + " " + text + " is too " + why + " to compute with in float",
                    "only its direction matters: scale it to a length near 1");
        }
    }

    /** Why float cannot normalise {@code d}, whose coordinates are finite: "zero", "long" or "short"; else null. */
    static String unusable(Vector3f d) {
        float squared = d.dot(d);
        if (d.x() == 0 && d.y() == 0 && d.z() == 0) {
            return "zero";
        }
        return Float.isInfinite(squared) ? "long" : squared < Float.MIN_NORMAL ? "short" : null;
    }

    /** "the radius must be greater than 0, found -1" at number {@code k} of group {@code g}. */
    private static SceneException must(StatementValues v, int g, int k, String name, String what, String help) {
        return v.errorAtValue(g, k, "the " + name + " must be " + what + ", found " + v.written(g, k), help);
    }

    /** A number for a message or a hint without a trailing ".0": 180, -0.5. */
    static String plain(float value) {
        return value == Math.rint(value) ? String.valueOf((long) value) : String.valueOf(value);
    }
}
