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
        // plain numbers, no arrays: a first run makes a million boxes before the JIT could take arrays away
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        double maxZ = Double.NEGATIVE_INFINITY;
        double largest = 0;
        for (Vector3f p : points) {
            minX = Math.min(minX, p.x());
            minY = Math.min(minY, p.y());
            minZ = Math.min(minZ, p.z());
            maxX = Math.max(maxX, p.x());
            maxY = Math.max(maxY, p.y());
            maxZ = Math.max(maxZ, p.z());
            largest = Math.max(largest, Math.max(Math.abs(p.x()), Math.max(Math.abs(p.y()), Math.abs(p.z()))));
        }
        double grow = grow(margin, largest);
        return new BoundingBox(new Vector3f(down(minX - grow), down(minY - grow), down(minZ - grow)),
                new Vector3f(up(maxX + grow), up(maxY + grow), up(maxZ + grow)));
    }

    /**
     * Writes the box {@link #around} makes, for the {@code count} points whose x, y, z follow each
     * other in {@code points} from {@code from}, to {@code into[at .. at+5]} as {@link #put} writes
     * it, with no object made: a scene may have a million triangles to measure.
     */
    static void putAround(double margin, float[] points, int from, int count, float[] into, int at) {
        double largest = 0;
        for (int axis = 0; axis < 3; axis++) {
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int p = from + axis; p < from + 3 * count; p += 3) {
                min = Math.min(min, points[p]);
                max = Math.max(max, points[p]);
                largest = Math.max(largest, Math.abs(points[p]));
            }
            into[at + axis] = (float) min; // grown below, once the largest coordinate is known
            into[at + 3 + axis] = (float) max;
        }
        double grow = grow(margin, largest);
        for (int axis = 0; axis < 3; axis++) {
            into[at + axis] = down(into[at + axis] - grow);
            into[at + 3 + axis] = up(into[at + 3 + axis] + grow);
        }
    }

    /** How far a box grows beyond its points: {@code margin} and a few rounding errors of their largest coordinate. */
    private static double grow(double margin, double largest) {
        return margin * (1 + 1e-6) + 8 * UNIT_ROUNDOFF * largest;
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
