package rtd.geometry;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * An infinite plane through a point Q with a normal n (Part II, "Geometry"). It has no box:
 * a bounding volume hierarchy keeps it beside the tree and tests it for every ray.
 *
 * @param point  a point Q of the plane
 * @param normal its normal n, of any length but not zero
 */
public record Plane(Vector3f point, Vector3f normal, Color color, Material material) implements IGeometry {

    /**
     * {@code t = ((Q − O)·n) / (R·n)}; no hit where the ray runs parallel to the plane
     * ({@code R·n = 0}) or meets it behind its origin.
     */
    @Override
    public Intersection intersect(Ray ray) {
        return intersect(ray, TestObserver.NONE);
    }

    @Override
    public Intersection intersect(Ray ray, TestObserver watch) {
        Vector3f o = ray.origin();
        Vector3f d = ray.direction();
        return Intersection.at(ray, hit(point.x(), point.y(), point.z(), normal.x(), normal.y(), normal.z(),
                o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), watch));
    }

    /**
     * The test on numbers: Q, n, the ray's O and R; t of the hit, or NaN. Every renderer runs
     * it: {@link #intersect}, and the accelerators on the numbers they keep.
     */
    public static float hit(float qx, float qy, float qz, float nx, float ny, float nz, float ox, float oy, float oz,
            float dx, float dy, float dz, TestObserver watch) {
        float facing = (dx * nx) + (dy * ny) + (dz * nz);                                 // R·n
        float along = ((qx - ox) * nx) + ((qy - oy) * ny) + ((qz - oz) * nz);             // (Q − O)·n
        float t = along / facing; // NaN or infinite if facing is 0
        watch.plane(facing, along, t);
        return t >= 0 && t < Float.POSITIVE_INFINITY && facing != 0 ? t : Float.NaN;
    }

    /** {@code n / |n|}, the same everywhere. */
    @Override
    public Vector3f normalAt(Vector3f hitPoint) {
        return normal.normalize();
    }

    @Override
    public BoundingBox bounds() {
        return BoundingBox.UNBOUNDED;
    }

    /** A surface, not a solid: a ray that meets it from behind meets its back. */
    @Override
    public boolean isSolid() {
        return false;
    }

    @Override
    public String kind() {
        return "plane";
    }
}
