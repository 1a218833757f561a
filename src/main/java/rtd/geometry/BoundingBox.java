package rtd.geometry;

import rtd.math.Vector3f;

/**
 * An axis-aligned box, given by its lowest and highest corner: a shape's bounds, which the
 * engine sorts objects by. {@link #UNBOUNDED} is the box
 * of an object without limits, such as a plane.
 */
public record BoundingBox(Vector3f min, Vector3f max) {

    /** The box of an object that reaches infinitely far: all of space. */
    public static final BoundingBox UNBOUNDED = new BoundingBox(
            new Vector3f(Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY),
            new Vector3f(Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY));

    /** Unit roundoff of {@code float}: the largest relative error of one rounding. */
    static final float UNIT_ROUNDOFF = 0x1p-24f;

    /** Whether the box is finite; {@link #UNBOUNDED} and any box with an infinite side are not. */
    public boolean isBounded() {
        return min.isFinite() && max.isFinite();
    }

    /** The box's centre, by which the hierarchy sorts the objects. */
    public Vector3f centre() {
        return min.add(max).multiply(0.5f);
    }

    /**
     * The box around {@code points}, grown on every side by {@code margin} plus a few rounding
     * errors of the largest coordinate, and rounded outwards: room for the points that a float
     * intersection test computes near the object.
     */
    static BoundingBox around(double margin, Vector3f... points) {
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double largest = 0;
        for (Vector3f p : points) {
            double[] c = {p.x(), p.y(), p.z()};
            for (int k = 0; k < 3; k++) {
                lo[k] = Math.min(lo[k], c[k]);
                hi[k] = Math.max(hi[k], c[k]);
                largest = Math.max(largest, Math.abs(c[k]));
            }
        }
        double grow = margin * (1 + 1e-6) + 8 * UNIT_ROUNDOFF * largest;
        return new BoundingBox(
                new Vector3f(down(lo[0] - grow), down(lo[1] - grow), down(lo[2] - grow)),
                new Vector3f(up(hi[0] + grow), up(hi[1] + grow), up(hi[2] + grow)));
    }

    /** Writes this box to {@code into[at .. at+5]}: min x, y, z, max x, y, z. */
    public void put(float[] into, int at) {
        into[at] = min.x();
        into[at + 1] = min.y();
        into[at + 2] = min.z();
        into[at + 3] = max.x();
        into[at + 4] = max.y();
        into[at + 5] = max.z();
    }

    private static float down(double value) {
        return Math.nextDown((float) value);
    }

    private static float up(double value) {
        return Math.nextUp((float) value);
    }
}
