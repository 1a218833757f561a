package rtd.explain;

import java.math.BigDecimal;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Vector3f;

/**
 * How {@code --explain} writes numbers: each float as the shortest decimal that reads back as the same float (so a
 * student who types it into a calculator starts from rtd's own number), without an exponent where that stays short;
 * points and vectors as the scene file writes them, {@code (x|y|z)}.
 */
final class Numbers {

    private Numbers() {
    }

    /** {@code 0.1f} as "0.1", {@code 20f} as "20", {@code 1e-9f} as "1.0E-9". */
    static String of(float value) {
        if (Float.isNaN(value)) {
            return "NaN";
        }
        if (Float.isInfinite(value)) {
            return value > 0 ? "∞" : "−∞";
        }
        float magnitude = Math.abs(value);
        if (magnitude != 0 && (magnitude < 1e-6f || magnitude >= 1e9f)) {
            return Float.toString(value);
        }
        return new BigDecimal(Float.toString(value)).stripTrailingZeros().toPlainString();
    }

    static String of(Vector3f v) {
        return of(v.x(), v.y(), v.z());
    }

    /** A colour as light, {@code (r|g|b)} from 0 to 1. */
    static String of(Rgb c) {
        return of(c.red(), c.green(), c.blue());
    }

    static String of(float x, float y, float z) {
        return "(" + of(x) + "|" + of(y) + "|" + of(z) + ")";
    }

    static String of(Color c) {
        return c.toString(); // the paper's 8-bit colour, (R|G|B)
    }

    /** The pixel's colour as {@code R G B}, the form the issue and the tests read. */
    static String rgb(Color c) {
        return c.red() + " " + c.green() + " " + c.blue();
    }
}
