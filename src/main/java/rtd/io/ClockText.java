package rtd.io;

import java.math.BigDecimal;
import java.math.MathContext;

/**
 * A clock value as messages and the progress line write it (Part III, "Expressions, named values and the
 * clock"): at most six significant digits, no trailing zeros, {@code 0.75}, {@code 0.333333}, {@code 1}.
 */
public final class ClockText {

    private ClockText() {
    }

    public static String format(double clock) {
        if (clock == 0) {
            return "0";
        }
        return new BigDecimal(clock).round(new MathContext(6)).stripTrailingZeros().toPlainString();
    }

    /** An expression as written, its value, and the clock if it uses it: "1-2*clock, which is -0.5 at clock = 0.75". */
    static String withValue(String text, float value, boolean usesClock, double clock) {
        String number = value == Math.rint(value) && Math.abs(value) < 1e9 ? String.valueOf((long) value)
                : String.valueOf(value);
        return text + ", which is " + number + (usesClock ? " at clock = " + format(clock) : "");
    }
}
