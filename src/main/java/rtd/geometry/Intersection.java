package rtd.geometry;

import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * What an intersection test found (paper, section 4.2.2): whether the ray hit the object, and
 * if so where.
 *
 * <p>It holds plain numbers: the ray parameter t of the hit and the hit point's coordinates.
 * A record of numbers only is one that the JIT keeps in registers; had it a {@code Vector3f}
 * or the {@code Ray} as a field, Java 17 would allocate that object for every test.
 *
 * @param t the ray parameter of the nearest hit with {@code t ≥ 0}, or NaN if there is none
 * @param x the x coordinate of the hit point
 * @param y the y coordinate of the hit point
 * @param z the z coordinate of the hit point
 */
public record Intersection(float t, float x, float y, float z) {

    /** The result of a test whose nearest hit lies at {@code t} on {@code ray} (NaN: none). */
    public static Intersection at(Ray ray, float t) {
        Vector3f point = ray.pointAt(t);
        return new Intersection(t, point.x(), point.y(), point.z());
    }

    /** Whether the ray hits the object at some {@code t ≥ 0}. */
    public boolean happened() {
        return t >= 0; // false for NaN
    }

    /** The hit point {@code P = O + t·R} (equation 3.1), the paper's {@code contactCoord}. */
    public Vector3f contactCoord() {
        return new Vector3f(x, y, z);
    }
}
