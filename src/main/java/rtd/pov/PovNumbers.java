package rtd.pov;

import java.math.BigDecimal;
import java.util.Locale;

/** Numbers as POV-Ray's scene files take them: plain decimals that POV-Ray reads as the very numbers rtd holds. */
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
}
