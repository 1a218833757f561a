package rtd.geometry;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * An axis-aligned box between two opposite corners (Part II, "Geometry").
 *
 * @param min the corner with the smallest coordinates
 * @param max the corner with the largest coordinates
 */
public record Box(Vector3f min, Vector3f max, Color color, Material material) implements IGeometry {

    /** A box between two opposite corners given in any order. */
    public static Box between(Vector3f a, Vector3f b, Color color, Material material) {
        return new Box(new Vector3f(Math.min(a.x(), b.x()), Math.min(a.y(), b.y()), Math.min(a.z(), b.z())),
                new Vector3f(Math.max(a.x(), b.x()), Math.max(a.y(), b.y()), Math.max(a.z(), b.z())), color, material);
    }

    /** How many numbers {@link #putTestNumbers} writes. */
    public static final int NUMBERS = 6;

    /**
     * The slab test ({@link #hit}) on this box's corners: where the ray enters the box, or, if
     * it starts inside, where it leaves it.
     */
    @Override
    public Intersection intersect(Ray ray) {
        return intersect(ray, TestObserver.NONE);
    }

    @Override
    public Intersection intersect(Ray ray, TestObserver watch) {
        float[] corners = new float[NUMBERS];
        putTestNumbers(corners, 0);
        Vector3f o = ray.origin();
        Vector3f d = ray.direction();
        return Intersection.at(ray, hit(corners, 0, o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), watch));
    }

    /**
     * Writes the {@value #NUMBERS} numbers {@link #hit} reads into {@code into} from {@code at}:
     * the smallest corner's x, y, z, then the largest's.
     */
    public void putTestNumbers(float[] into, int at) {
        into[at] = min.x();
        into[at + 1] = min.y();
        into[at + 2] = min.z();
        into[at + 3] = max.x();
        into[at + 4] = max.y();
        into[at + 5] = max.z();
    }

    /**
     * The slab test of the ray O + t·D against the box whose corners {@link #putTestNumbers}
     * wrote at {@code numbers[at]}: along each axis the ray is between the box's two faces for an
     * interval of t; the box is where all three intervals overlap. The ray hits where it enters
     * that overlap, or, if it starts inside, where it leaves it: that t, or NaN for no hit. Every
     * renderer runs it: {@link #intersect}, and the accelerators on the numbers they keep.
     */
    public static float hit(float[] numbers, int at, float ox, float oy, float oz, float dx, float dy, float dz,
            TestObserver watch) {
        float enter = Float.NEGATIVE_INFINITY;
        float exit = Float.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            float o = k == 0 ? ox : k == 1 ? oy : oz;
            float d = k == 0 ? dx : k == 1 ? dy : dz;
            float lo = numbers[at + k];
            float hi = numbers[at + 3 + k];
            if (d == 0) { // parallel to this slab: inside it everywhere or nowhere
                boolean outside = o < lo || o > hi;
                watch.parallelSlab(k, outside);
                if (outside) {
                    return Float.NaN;
                }
                continue;
            }
            float t0 = (lo - o) / d;
            float t1 = (hi - o) / d;
            watch.slab(k, t0, t1);
            enter = Math.max(enter, Math.min(t0, t1));
            exit = Math.min(exit, Math.max(t0, t1));
        }
        watch.slabs(enter, exit);
        float t = enter >= 0 ? enter : exit;
        if (enter > exit || exit < 0 || !Float.isFinite(t)) { // infinite: a direction of no length
            return Float.NaN;
        }
        return t;
    }

    /** The normal of the face the point lies on: the axis along which it is nearest a face. */
    @Override
    public Vector3f normalAt(Vector3f point) {
        return faceNormal(point, new Vector3f(1, 1, 1));
    }

    /**
     * The normal of the face the ray crosses at {@code point}: of the six faces' planes, the one
     * the ray meets nearest to the point, measured along the ray ({@code |P − face| / |R|} on
     * each axis). At an edge the ray crosses one face and runs past the other; a ray that runs
     * along a face's plane never crosses it, so that face is never chosen.
     */
    @Override
    public Vector3f normalAt(Vector3f point, Vector3f direction) {
        return faceNormal(point, direction);
    }

    private Vector3f faceNormal(Vector3f point, Vector3f direction) {
        float[] p = {point.x(), point.y(), point.z()};
        float[] d = {direction.x(), direction.y(), direction.z()};
        float[] lo = {min.x(), min.y(), min.z()};
        float[] hi = {max.x(), max.y(), max.z()};
        int axis = 0;
        float sign = -1;
        float nearest = Float.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            float toLow = Math.abs(p[k] - lo[k]) / Math.abs(d[k]); // ∞ or NaN where the ray runs along the face
            float toHigh = Math.abs(hi[k] - p[k]) / Math.abs(d[k]);
            if (toLow < nearest) {
                nearest = toLow;
                axis = k;
                sign = -1;
            }
            if (toHigh < nearest) {
                nearest = toHigh;
                axis = k;
                sign = 1;
            }
        }
        return new Vector3f(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
    }

    /** The box itself, grown by a few rounding errors of its coordinates. */
    @Override
    public BoundingBox bounds() {
        return BoundingBox.around(0, min, max);
    }

    @Override
    public String kind() {
        return "box";
    }
}
