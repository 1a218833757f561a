package rtd.geometry;

/**
 * A flat round cap of a cylinder or a cone (Part III, "More shapes"): the points of the plane
 * through its centre C at right angles to the axis that lie within its radius of C. A cap of
 * radius 0 is the one point C.
 */
final class Disc {

    private Disc() {
    }

    /**
     * The cap at end {@code end} (0: the first, 1: the second) with centre C, axis h and radius
     * r, and the ray O + t·R: the plane's test ({@link Plane#hit}), then whether the point
     * {@code P = O + t·R} lies within r of C ({@code |P − C|² ≤ r²}). Returns t, or NaN.
     */
    static float hit(int end, float cx, float cy, float cz, float hx, float hy, float hz, float r,
            float ox, float oy, float oz, float dx, float dy, float dz, TestObserver watch) {
        float t = Plane.hit(cx, cy, cz, hx, hy, hz, ox, oy, oz, dx, dy, dz, TestObserver.NONE);
        if (!(t >= 0)) {
            watch.cap(end, Float.NaN, Float.NaN, r * r);
            return Float.NaN;
        }
        float px = (ox + dx * t) - cx;                  // P − C, with P as Intersection.at computes it
        float py = (oy + dy * t) - cy;
        float pz = (oz + dz * t) - cz;
        float fromCentre = px * px + py * py + pz * pz; // |P − C|²
        watch.cap(end, t, fromCentre, r * r);
        return fromCentre <= r * r ? t : Float.NaN;
    }

    /**
     * The nearest of {@code side}, the hit of the solid's side (NaN: none), and of its two caps, at A
     * of radius r1 and at B of radius r2, both at right angles to the unit axis h; telling
     * {@code watch} which part it is. Returns t, or NaN.
     */
    static float nearestWithCaps(float side, float ax, float ay, float az, float r1, float bx, float by, float bz,
            float r2, float hx, float hy, float hz, float ox, float oy, float oz, float dx, float dy, float dz,
            TestObserver watch) {
        float t = side;
        String part = t >= 0 ? "side" : "none";
        float cap = hit(0, ax, ay, az, hx, hy, hz, r1, ox, oy, oz, dx, dy, dz, watch);
        if (nearer(cap, t)) {
            t = cap;
            part = "first cap";
        }
        cap = hit(1, bx, by, bz, hx, hy, hz, r2, ox, oy, oz, dx, dy, dz, watch);
        if (nearer(cap, t)) {
            t = cap;
            part = "second cap";
        }
        watch.nearestPart(part, t);
        return t >= 0 ? t : Float.NaN;
    }

    /**
     * Whether {@code t} is a hit ({@code ≥ 0}) nearer than {@code best} (NaN: none yet); on a tie the earlier stays.
     */
    static boolean nearer(float t, float best) {
        return t >= 0 && !(t >= best);
    }
}
