package rtd.geometry;

import java.util.List;
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
        float facing = ray.direction().dot(normal);
        float t = point.subtract(ray.origin()).dot(normal) / facing; // NaN or infinite if facing is 0
        return Intersection.at(ray, t >= 0 && t < Float.POSITIVE_INFINITY && facing != 0 ? t : Float.NaN);
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

    /** The same shape in the same place, whatever its colour and finish. */
    @Override
    public Object sameTest() {
        return List.of(point, normal);
    }

    @Override
    public String kind() {
        return "plane";
    }
}
