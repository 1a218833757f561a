package rtd.geometry;

/**
 * The side of a cylinder or a cone (Part III, "More shapes"): the roots of its quadratic
 * {@code a·t² + b·t + c = 0} that lie between the two ends.
 */
final class SideRoots {

    private SideRoots() {
    }

    /**
     * The nearest root {@code t ≥ 0} at which the ray's point lies between the ends,
     * {@code 0 ≤ s = h·w + t·(h·R) ≤ length} along the unit axis h from the first end; NaN if
     * none. The roots are {@code (−b ∓ √(b² − 4ac))/2a}; where {@code a = 0} the equation is
     * {@code b·t + c = 0}, one root (a cone's ray parallel to its slant; a cylinder's ray along
     * its axis, whose b is 0 too, meets no side).
     */
    static float nearest(float a, float b, float c, float hw, float hd, float length, TestObserver watch) {
        float discriminant = b * b - 4 * a * c;
        watch.side(a, b, c, discriminant);
        if (a == 0) {
            return b == 0 ? Float.NaN : between(-c / b, hw, hd, length, Float.NaN, watch);
        }
        if (!(discriminant >= 0)) {
            return Float.NaN;
        }
        float root = (float) Math.sqrt(discriminant);
        float best = between((-b - root) / (2 * a), hw, hd, length, Float.NaN, watch);
        return between((-b + root) / (2 * a), hw, hd, length, best, watch);
    }

    /** {@code t} if it lies between the ends and is a hit nearer than {@code best}, else {@code best}. */
    private static float between(float t, float hw, float hd, float length, float best, TestObserver watch) {
        float along = hw + t * hd;                            // s = h·(w + t·R)
        boolean between = along >= 0 && along <= length;
        watch.sideRoot(t, along, between);
        return between && Disc.nearer(t, best) ? t : best;
    }
}
