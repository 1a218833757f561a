package rtd.geometry;

import rtd.math.Vector3f;

/**
 * An axis-aligned box, given by its lowest and highest corner. A bounding volume hierarchy
 * ({@code rtd.accel.Bvh}) sorts objects into a tree of such boxes. {@link #UNBOUNDED} is the box
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

    /**
     * {@link #around} for one point {@code (x, y, z)}, written to {@code into[at .. at+5]} (min x,
     * y, z, max x, y, z) instead of a new box: the same numbers, without making objects, for a
     * hierarchy that measures a million of them.
     */
    static void around(double margin, float x, float y, float z, float[] into, int at) {
        double largest = Math.max(Math.max(Math.max(0, Math.abs((double) x)), Math.abs((double) y)), Math.abs((double) z));
        double grow = margin * (1 + 1e-6) + 8 * UNIT_ROUNDOFF * largest;
        into[at] = down(x - grow);
        into[at + 1] = down(y - grow);
        into[at + 2] = down(z - grow);
        into[at + 3] = up(x + grow);
        into[at + 4] = up(y + grow);
        into[at + 5] = up(z + grow);
    }

    /**
     * {@link #around} for the {@code points} points whose coordinates are
     * {@code coords[from ..]} (x, y, z each), written to {@code into[at .. at+5]} instead of a
     * new box: the same numbers (a minimum or maximum is the same in any order), without making
     * objects.
     */
    static void around(double margin, float[] coords, int from, int points, float[] into, int at) {
        double largest = 0;
        for (int i = from; i < from + 3 * points; i++) {
            largest = Math.max(largest, Math.abs((double) coords[i]));
        }
        double grow = margin * (1 + 1e-6) + 8 * UNIT_ROUNDOFF * largest;
        for (int k = 0; k < 3; k++) {
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (int p = 0; p < points; p++) {
                double c = coords[from + 3 * p + k];
                lo = Math.min(lo, c);
                hi = Math.max(hi, c);
            }
            into[at + k] = down(lo - grow);
            into[at + k + 3] = up(hi + grow);
        }
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
