package rtd.io;

import rtd.image.Color;
import rtd.math.Vector3f;

/**
 * The values of the statement being read, group by group, where each was written, and the
 * rules they must follow (the paper's scene file, section 4.1, and Part II's, "The scene file"):
 * every number finite, a radius, zoom or scale above 0, a direction not zero, a colour channel a
 * whole number from 0 to 255, and so on. A statement's {@link Statement.Builder} asks for its
 * groups here by their index; a broken rule becomes an error at the value that breaks it, worded
 * with the group's meaning ("the x of the centre must be a finite number").
 *
 * <p>What the reader found, and where, is kept by {@link WrittenValues}, which this extends
 * rather than holds: so the rules read the numbers as their own fields, and a reader fills one
 * such object for every line of the file, without an object per number.
 */
final class GroupValues extends WrittenValues {

    /** The values a reader fills line by line: room for the longest statements, which grows if need be. */
    GroupValues(SourceText source) {
        this(source, 16, 8);
    }

    private GroupValues(SourceText source, int numbers, int groups) {
        super(source, numbers, groups);
    }

    /**
     * An independent copy, for an object that is built when the whole file is read: its arrays
     * just long enough (a hundred thousand spheres that name a material keep a copy each).
     */
    GroupValues copy() {
        GroupValues copy = new GroupValues(source, count, groupCount);
        copy.statement = statement;
        copy.line = line;
        copy.lineStart = lineStart;
        System.arraycopy(values, 0, copy.values, 0, count);
        System.arraycopy(starts, 0, copy.starts, 0, count);
        System.arraycopy(ends, 0, copy.ends, 0, count);
        System.arraycopy(keys, 0, copy.keys, 0, count);
        copy.count = count;
        System.arraycopy(firsts, 0, copy.firsts, 0, groupCount);
        System.arraycopy(opens, 0, copy.opens, 0, groupCount);
        copy.groupCount = groupCount;
        return copy;
    }

    // ---- asked for by the builders ------------------------------------------------------

    /** The one number of group {@code g}, which must be finite. */
    float finite(int g) throws StatementError {
        return finite(firsts[g], meaning(g));
    }

    /** The one number of group {@code g}, which must be finite and greater than 0 (a radius, a zoom). */
    float positive(int g) throws StatementError {
        int i = firsts[g];
        float value = finite(i, meaning(g));
        if (value > 0) {
            return value;
        }
        throw errorAt(starts[i], "the " + meaning(g) + " must be greater than 0, found " + written(i),
                value < 0 ? "without its minus sign: " + number(-value)
                        : "a " + meaning(g) + " of 0 leaves nothing to see; give a number greater than 0, such as 1");
    }

    /** The one number of group {@code g}, finite and strictly between {@code low} and {@code high}. */
    float between(int g, float low, float high, String unit, String help) throws StatementError {
        int i = firsts[g];
        float value = finite(i, meaning(g));
        if (value > low && value < high) {
            return value;
        }
        throw errorAt(starts[i], "the " + meaning(g) + " must be greater than " + number(low) + " and less than "
                + number(high) + " " + unit + ", found " + written(i), help);
    }

    /** The three numbers of group {@code g} as a vector of finite numbers. */
    Vector3f vector(int g) throws StatementError {
        int i = firsts[g];
        for (int k = 0; k < 3; k++) {
            if (!Float.isFinite(values[i + k])) {
                finite(i + k, "xyz".charAt(k) + " of the " + meaning(g));
            }
        }
        return new Vector3f(values[i], values[i + 1], values[i + 2]);
    }

    /**
     * The three numbers of group {@code g} as a direction: finite, not zero, and neither too short
     * nor too long to compute with in float (a view direction, a plane's normal).
     */
    Vector3f direction(int g, String zeroHelp) throws StatementError {
        Vector3f direction = vector(g);
        int i = firsts[g];
        if (direction.x() == 0 && direction.y() == 0 && direction.z() == 0) {
            throw errorAt(starts[i], "the " + meaning(g) + " must not be zero, found " + groupText(g), zeroHelp);
        }
        float squaredLength = direction.dot(direction);
        if (!(squaredLength >= Float.MIN_NORMAL) || Float.isInfinite(squaredLength)) {
            throw errorAt(starts[i], "the " + meaning(g) + " " + groupText(g) + " is too "
                    + (Float.isInfinite(squaredLength) ? "long" : "short") + " to compute with in float",
                    "only its direction matters: scale it to a length near 1");
        }
        return direction;
    }

    /** The three numbers of group {@code g}: a colour, each channel a whole number from 0 to 255. */
    Color colour(int g) throws StatementError {
        int i = firsts[g];
        return new Color(channel(i, "red", i), channel(i + 1, "green", i), channel(i + 2, "blue", i));
    }

    /**
     * The value of {@code key} in the properties of group {@code g}, or {@code fallback} if the
     * group does not give it; a given value must be finite and at least {@code minimum}.
     */
    float property(int g, String key, float fallback, float minimum) throws StatementError {
        int index = statement.groups().get(g).keys().indexOf(key);
        int end = g + 1 < groupCount ? firsts[g + 1] : count;
        for (int i = firsts[g]; i < end; i++) {
            if (keys[i] == index) {
                String name = "value of '" + key + "'";
                float value = finite(i, name);
                if (value >= minimum) {
                    return value;
                }
                throw errorAt(starts[i], "the " + name + " must be at least " + number(minimum) + ", found " + written(i),
                        minimum > 0 ? "an index of refraction is 1 for air, 1.33 for water, 1.5 for glass"
                                : "0 turns this part of the finish off");
            }
        }
        return fallback;
    }

    // ---- the rules --------------------------------------------------------------------------

    /** Number {@code i}, which must be finite (not NaN, not infinite, not beyond a float's range). */
    private float finite(int i, String name) throws StatementError {
        float value = values[i];
        if (Float.isFinite(value)) {
            return value;
        }
        String written = written(i);
        boolean overflow = !written.contains("NaN") && !written.contains("Infinity");
        throw errorAt(starts[i], "the " + name + " must be a finite number, found " + written
                + (overflow ? ", which is too large for a float" : ""),
                overflow ? "a float holds numbers up to about 3.4e38"
                        : "NaN (not a number) and Infinity are not numbers a scene can use; give a finite number");
    }

    /** Number {@code i}, the {@code name} channel of the colour whose numbers start at {@code first}. */
    private int channel(int i, String name, int first) throws StatementError {
        float value = values[i];
        if (!(value >= 0 && value <= 255 && value == Math.rint(value))) {
            String fractions = fractionsHint(first);
            throw errorAt(starts[i], "the " + name + " channel must be a whole number from 0 to 255, found "
                    + written(i), fractions != null ? fractions
                            : "each channel runs from 0 (none of that colour) to 255 (all of it), in whole numbers");
        }
        return (int) value;
    }

    /**
     * For a colour written as fractions from 0 to 1, as other programs write colours, the same
     * colour from 0 to 255; otherwise no hint.
     */
    private String fractionsHint(int first) {
        StringBuilder scaled = new StringBuilder("(");
        for (int i = first; i < first + 3; i++) {
            if (!(values[i] >= 0 && values[i] <= 1)) {
                return null;
            }
            scaled.append(i > first ? "|" : "").append(Math.round(values[i] * 255));
        }
        return "rtd's colours run from 0 to 255, not from 0 to 1: this colour is " + scaled + ")";
    }

    private String meaning(int g) {
        return g < statement.groups().size() ? statement.groups().get(g).meaning() : Statement.MATERIAL.meaning();
    }

    private String groupText(int g) {
        int end = g + 1 < groupCount ? firsts[g + 1] : count;
        StringBuilder text = new StringBuilder("(");
        for (int i = firsts[g]; i < end; i++) {
            text.append(i > firsts[g] ? "|" : "").append(written(i));
        }
        return text.append(')').toString();
    }

    /** 180 rather than 180.0 in a message. */
    private static String number(float value) {
        return value == Math.rint(value) ? String.valueOf((long) value) : String.valueOf(value);
    }
}
