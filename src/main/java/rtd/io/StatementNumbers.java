package rtd.io;

import rtd.io.StatementReader.StatementError;
import rtd.math.Vector3f;
import rtd.image.Color;

/**
 * The numbers of the statement being read, where each was written, and the rules they must
 * follow (SPEC.md, "The scene file"): finite, a radius and a zoom above 0, a view direction that
 * is not zero, colour channels that are whole numbers from 0 to 255. A broken rule becomes an
 * error at the number that breaks it.
 */
final class StatementNumbers {

    /** Makes the error for a number that breaks a rule. */
    interface Errors {
        StatementError at(int offset, String message, String help);
    }

    private final SourceText source;
    private final Errors errors;
    private final float[] values = new float[8];
    private final int[] starts = new int[8];
    private final int[] ends = new int[8];

    StatementNumbers(SourceText source, Errors errors) {
        this.source = source;
        this.errors = errors;
    }

    /** Keeps number {@code i} of the statement, written at {@code bytes[start, end)}. */
    void set(int i, float value, int start, int end) {
        values[i] = value;
        starts[i] = start;
        ends[i] = end;
    }

    /** Number {@code i}, which must be finite (not NaN, not infinite, not beyond a float's range). */
    float finite(int i, String name) throws StatementError {
        float value = values[i];
        if (Float.isFinite(value)) {
            return value;
        }
        String written = source.text(starts[i], ends[i]);
        boolean overflow = !written.contains("NaN") && !written.contains("Infinity");
        throw errors.at(starts[i], "the " + name + " must be a finite number, found " + written
                + (overflow ? ", which is too large for a float" : ""),
                overflow ? "a float holds numbers up to about 3.4e38" : null);
    }

    /** The three numbers from {@code i} on as a vector; {@code name} is only read for a message. */
    Vector3f finiteVector(int i, String name) throws StatementError {
        for (int k = 0; k < 3; k++) {
            if (!Float.isFinite(values[i + k])) {
                finite(i + k, "xyz".charAt(k) + " of the " + name);
            }
        }
        return new Vector3f(values[i], values[i + 1], values[i + 2]);
    }

    /** Number {@code i}, which must be finite and greater than 0 (a radius, a zoom). */
    float positive(int i, String name) throws StatementError {
        float value = finite(i, name);
        if (value > 0) {
            return value;
        }
        throw errors.at(starts[i], "the " + name + " must be greater than 0, found " + source.text(starts[i], ends[i]), null);
    }

    /** Numbers {@code i} to {@code i + 2}: a view direction, not zero and not too short or long for float. */
    Vector3f viewDirection(int i) throws StatementError {
        Vector3f direction = finiteVector(i, "view direction");
        float squaredLength = direction.dot(direction);
        if (direction.x() == 0 && direction.y() == 0 && direction.z() == 0) {
            throw errors.at(starts[i], "the view direction must not be zero, found " + groupText(i, 3),
                    "the camera looks along it; (0|0|-1) looks into the screen");
        }
        if (!(squaredLength >= Float.MIN_NORMAL) || Float.isInfinite(squaredLength)) {
            throw errors.at(starts[i], "the view direction " + groupText(i, 3) + " is too "
                    + (Float.isInfinite(squaredLength) ? "long" : "short") + " to compute with in float",
                    "only its direction matters: scale it to a length near 1");
        }
        return direction;
    }

    /** Numbers {@code i} to {@code i + 2}: a colour, each channel a whole number from 0 to 255. */
    Color colour(int i) throws StatementError {
        return new Color(channel(i, "red"), channel(i + 1, "green"), channel(i + 2, "blue"));
    }

    private int channel(int i, String name) throws StatementError {
        float value = values[i];
        if (!(value >= 0 && value <= 255 && value == Math.rint(value))) {
            throw errors.at(starts[i], "the " + name + " channel must be a whole number from 0 to 255, found "
                    + source.text(starts[i], ends[i]), null);
        }
        return (int) value;
    }

    private String groupText(int i, int size) {
        StringBuilder text = new StringBuilder("(");
        for (int k = 0; k < size; k++) {
            text.append(k > 0 ? "|" : "").append(source.text(starts[i + k], ends[i + k]));
        }
        return text.append(')').toString();
    }

    // ---- reading bytes ------------------------------------------------------------------
}
