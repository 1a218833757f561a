package rtd.geometry;

import rtd.image.Color;

/**
 * Watches a {@link Pattern} choose a colour, for {@code --explain}: the point in the pattern's
 * space, the number its rule computed (floor(x), the fraction of x, floor(√(x² + z²)) or
 * floor(x) + floor(y) + floor(z)) and the colour it gave. Renderers pass {@link #NONE}.
 */
public interface PatternObserver {

    /** Watches nothing. */
    PatternObserver NONE = (pattern, x, y, z, value, colour) -> {
    };

    /** {@code pattern} gave {@code colour} at (x, y, z) of its space, where its rule computed {@code value}. */
    void pattern(Pattern pattern, double x, double y, double z, double value, Color colour);
}
