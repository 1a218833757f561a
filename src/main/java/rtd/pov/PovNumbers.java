package rtd.pov;

import java.math.BigDecimal;
import java.util.Locale;
import rtd.image.Rgb;
import rtd.math.Vector3f;

/**
 * Numbers as POV-Ray's scene files take them: plain decimals that POV-Ray reads as the very numbers rtd holds, and the
 * vectors and colours made of them.
 */
final class PovNumbers {

    private PovNumbers() {
    }

    /** A float exactly as rtd holds it (its shortest decimal); POV-Ray reads it as the same number. */
    static String num(float value) {
        return new BigDecimal(Float.toString(value)).stripTrailingZeros().toPlainString();
    }

    /** A double to 17 significant digits, plain. */
    static String num(double value) {
        if (value == 0) {
            return "0";
        }
        return new BigDecimal(String.format(Locale.ROOT, "%.17g", value)).stripTrailingZeros().toPlainString();
    }

    static String rgb(Rgb c) {
        return "rgb <" + num(c.red()) + ", " + num(c.green()) + ", " + num(c.blue()) + ">";
    }

    static String vector(Vector3f v) {
        return vector(d(v));
    }

    /** A vector worked out in double as {@code <x, y, z>}. */
    static String vector(double[] v) {
        return "<" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + ">";
    }

    /** {@code v} in double, for the vectors the export works out: {@link #plus}, {@link #times}. */
    static double[] d(Vector3f v) {
        return new double[] {v.x(), v.y(), v.z()};
    }

    static double[] plus(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    static double[] times(double[] a, double f) {
        return new double[] {a[0] * f, a[1] * f, a[2] * f};
    }
}
