package rtd.io;

import java.nio.charset.StandardCharsets;

/**
 * Reads a decimal number from the file's bytes, rounded as {@link Float#parseFloat} does, without a String
 * (a million spheres have seven million numbers): a sign, digits with an optional point ({@code 1.},
 * {@code .5}), an optional exponent; also {@code NaN} and {@code Infinity}, for the caller to refuse.
 */
final class FloatParser {

    private static final double[] POWERS = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    private static final int MAX_DIGITS = 18;

    private FloatParser() {
    }

    /** The number in {@code bytes[start, end)}; a {@link NumberFormatException} if the text is not one. */
    static float parse(byte[] bytes, int start, int end) {
        int i = start < end && (bytes[start] == '+' || bytes[start] == '-') ? start + 1 : start;
        if (i < end && (bytes[i] == 'N' || bytes[i] == 'I')) {
            return special(new String(bytes, i, end - i, StandardCharsets.US_ASCII), bytes[start] == '-');
        }
        long number = leading(bytes, start, end);
        if ((int) (number >>> 32) != end) {
            throw new NumberFormatException();
        }
        return Float.intBitsToFloat((int) number);
    }

    /**
     * The number that {@code bytes[start, end)} starts with, no NaN or Infinity, so that a reader needs no second
     * pass to find where it ends: its float's bits in the low 32 bits, the offset after it in the high 32; −1 if no
     * number starts there.
     */
    static long leading(byte[] bytes, int start, int end) {
        int i = start;
        boolean negative = false;
        if (i < end && (bytes[i] == '+' || bytes[i] == '-')) {
            negative = bytes[i] == '-';
            i++;
        }
        long mantissa = 0;
        int digits = 0;
        int scale = 0;
        boolean exact = true;
        boolean anyDigit = false;
        boolean seenPoint = false;
        for (; i < end; i++) {
            byte c = bytes[i];
            if (c >= '0' && c <= '9') {
                anyDigit = true;
                if (mantissa == 0 && c == '0') {
                    scale -= seenPoint ? 1 : 0; // a leading zero is no significant digit
                } else if (digits < MAX_DIGITS) {
                    mantissa = mantissa * 10 + (c - '0');
                    digits++;
                    scale -= seenPoint ? 1 : 0;
                } else {
                    exact = false; // too many digits for a long: leave it to the JDK
                    scale += seenPoint ? 0 : 1;
                }
            } else if (c == '.' && !seenPoint) {
                seenPoint = true;
            } else {
                break;
            }
        }
        if (!anyDigit) {
            return -1;
        }
        if (i < end && (bytes[i] == 'e' || bytes[i] == 'E')) {
            i++;
            boolean negativeExponent = false;
            if (i < end && (bytes[i] == '+' || bytes[i] == '-')) {
                negativeExponent = bytes[i] == '-';
                i++;
            }
            int exponent = 0;
            int exponentDigits = 0;
            for (; i < end && bytes[i] >= '0' && bytes[i] <= '9'; i++) {
                exponent = Math.min(exponent * 10 + (bytes[i] - '0'), 100_000);
                exponentDigits++;
            }
            if (exponentDigits == 0) {
                return -1;
            }
            scale += negativeExponent ? -exponent : exponent;
        }
        float magnitude = exact ? fast(mantissa, scale) : Float.NaN;
        if (Float.isNaN(magnitude)) {
            magnitude = Math.abs(Float.parseFloat(new String(bytes, start, i - start, StandardCharsets.US_ASCII)));
        }
        return (long) i << 32 | Float.floatToRawIntBits(negative ? -magnitude : magnitude) & 0xFFFF_FFFFL;
    }

    /** Clinger's fast path: digits and power of ten exact in a double round once to it, again to float; else NaN. */
    private static float fast(long mantissa, int scale) {
        if (mantissa == 0 || mantissa >= (1L << 53) || Math.abs(scale) >= POWERS.length) {
            return mantissa == 0 ? 0f : Float.NaN;
        }
        double value = scale >= 0 ? mantissa * POWERS[scale] : mantissa / POWERS[-scale];
        // Rounding the double again to float is wrong only when the double lies exactly
        // halfway between two floats: its lowest 29 bits are then 1 followed by zeros.
        long lowBits = Double.doubleToRawLongBits(value) & ((1L << 29) - 1);
        return lowBits == (1L << 28) ? Float.NaN : (float) value;
    }

    /** NaN or an infinity, for the caller to refuse; out of {@link #parse}, which stays small for the JIT. */
    private static float special(String word, boolean negative) {
        if (!word.equals("NaN") && !word.equals("Infinity")) {
            throw new NumberFormatException();
        }
        return word.equals("NaN") ? Float.NaN : negative ? Float.NEGATIVE_INFINITY : Float.POSITIVE_INFINITY;
    }
}
