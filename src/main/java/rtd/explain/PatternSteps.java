package rtd.explain;

import rtd.geometry.Pattern;
import rtd.geometry.PatternObserver;
import rtd.image.Color;

/**
 * How a pattern chose a colour, explained (<i>The Ray Tracer Challenge</i>, chapter 10): the point in the pattern's
 * space and its rule's number, as {@link Pattern#colourAt} tells them: "floor(x) + floor(y) + floor(z) = 3: odd, so b".
 */
final class PatternSteps implements PatternObserver {

    private final Text text;

    PatternSteps(Text text) {
        this.text = text;
    }

    @Override
    public void pattern(Pattern pattern, double x, double y, double z, double value, Color colour) {
        text.line(pattern.kind().word() + " pattern, a = " + Numbers.of(pattern.a())
                + ", b = " + Numbers.of(pattern.b())
                + ", at (" + number(x) + "|" + number(y) + "|" + number(z) + ") in its space:");
        text.in().line(rule(pattern.kind(), value, colour)).out();
    }

    /** The rule with its number filled in, and the colour it gives. */
    static String rule(Pattern.Kind kind, double value, Color colour) {
        String parity = Pattern.isEven(value) ? "even, so a" : "odd, so b";
        return switch (kind) {
            case STRIPES -> "floor(x) = " + whole(value) + ": " + parity + " = " + Numbers.of(colour);
            case RINGS -> "floor(√(x² + z²)) = " + whole(value) + ": " + parity + " = " + Numbers.of(colour);
            case CHECKER -> "floor(x) + floor(y) + floor(z) = " + whole(value) + ": " + parity
                    + " = " + Numbers.of(colour);
            case GRADIENT -> "x − floor(x) = " + number(value) + ": a + (b − a)·" + number(value)
                    + ", each channel rounded = " + Numbers.of(colour);
        };
    }

    private static String whole(double value) {
        return String.valueOf((long) value);
    }

    /** A coordinate in the pattern's space, computed in double, to 6 decimals. */
    private static String number(double value) {
        return Numbers.of((float) (Math.round(value * 1e6) / 1e6));
    }
}
