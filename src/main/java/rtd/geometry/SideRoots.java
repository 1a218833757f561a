package rtd.geometry;

/**
 * The side of a cylinder or a cone (Part III, "More shapes"): the roots of its quadratic
 * {@code a·t² + b·t + c = 0} that lie between the two ends.
 */
final class SideRoots {

    private SideRoots() {
    }

    /**
     * The nearest root at which the ray's point lies between the ends,
     * {@code 0 ≤ s = h·w + t'·(h·R) ≤ length} along the unit axis h from the first end, as the
     * ray's {@code t = t0 + t' ≥ 0} ({@code t'} counts from {@code O' = O + t0·R}); NaN if none.
     * The roots are {@code (−b ∓ √(b² − 4ac))/2a}; where {@code a = 0} the equation is
     * {@code b·t' + c = 0}, one root (a cone's ray parallel to its slant; a cylinder's ray along
     * its axis, whose b is 0 too, meets no side).
     */
    static float nearest(float t0, float a, float b, float c, float hw, float hd, float length, TestObserver watch) {
        float discriminant = b * b - 4 * a * c;
        watch.side(t0, a, b, c, discriminant);
        if (a == 0) {
            return b == 0 ? Float.NaN : between(t0, -c / b, hw, hd, length, Float.NaN, watch);
        }
        if (!(discriminant >= 0)) {
            return Float.NaN;
        }
        float root = (float) Math.sqrt(discriminant);
        float best = between(t0, (-b - root) / (2 * a), hw, hd, length, Float.NaN, watch);
        return between(t0, (-b + root) / (2 * a), hw, hd, length, best, watch);
    }

    /**
     * The ray's {@code t = t0 + t'} of the root {@code t'} (counted from O') if it lies between the
     * ends and is a hit nearer than {@code best}, else {@code best}.
     */
    private static float between(float t0, float root, float hw, float hd, float length, float best,
            TestObserver watch) {
        float along = hw + root * hd;                         // s = h·(w + t'·R)
        boolean between = along >= 0 && along <= length;
        float t = t0 + root;
        watch.sideRoot(t, along, between);
        return between && Disc.nearer(t, best) ? t : best;
    }

    /**
     * The t of the ray's point O' nearest the middle M of the axis, {@code (M − O)·R / (R·R)}, from
     * which the side's quadratic is solved: there the vector {@code w = O' − A} is about as long
     * as the solid is large, however long the ray has run, and {@code c = w·w − …} keeps its digits
     * (computed from O itself, the difference of two squares of the ray's length would lose a
     * thin solid seen from afar; <i>Ray Tracing Gems</i>, chapter 7, does the same for spheres).
     */
    static float nearestTheMiddle(float ax, float ay, float az, float bx, float by, float bz,
            float ox, float oy, float oz, float dx, float dy, float dz) {
        float mx = (ax + bx) / 2 - ox;                        // M − O
        float my = (ay + by) / 2 - oy;
        float mz = (az + bz) / 2 - oz;
        float t0 = (mx * dx + my * dy + mz * dz) / (dx * dx + dy * dy + dz * dz);
        return Float.isFinite(t0) ? t0 : 0;
    }
}
