package rtd.geometry;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A sphere with a centre M, a radius r, a flat colour and a finish (paper, sections 3.2.2 and
 * 4.2.2).
 *
 * <p>{@link #intersect} solves the quadratic equation 3.5 in single precision, exactly in the
 * order of equations 3.6 to 3.8, so that it draws what the paper's program draws.
 */
public record Sphere(Vector3f center, float radius, Color color, Material material) implements IGeometry {

    /** A sphere with the default finish, as the paper's scene file gives one. */
    public Sphere(Vector3f center, float radius, Color color) {
        this(center, radius, color, Material.DEFAULT);
    }

    /**
     * Solves {@code a·t² + b·t + c = 0} (equation 3.5) and returns the smallest root
     * {@code t ≥ 0}: the nearer hit, or the far one when the ray starts inside the sphere.
     */
    @Override
    public Intersection intersect(Ray ray) {
        return intersect(ray, TestObserver.NONE);
    }

    /** {@link #intersect(Ray)}, telling {@code watch} each number of the test. */
    @Override
    public Intersection intersect(Ray ray, TestObserver watch) {
        Vector3f o = ray.origin();
        Vector3f d = ray.direction();
        return Intersection.at(ray, hit(center.x(), center.y(), center.z(), radius,
                o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), watch));
    }

    /**
     * The intersection test of the ray {@code O + t·R} and the sphere with centre M and radius r
     * (section 3.2.2): the quadratic of equation 3.5, its coefficients by equations 3.6 to 3.8.
     * Returns the smallest root {@code t ≥ 0}, or NaN. Every renderer runs this test: the
     * paper's loop through {@link #intersect}, the accelerators on the numbers they keep.
     */
    public static float hit(float mx, float my, float mz, float r, float ox, float oy, float oz,
            float dx, float dy, float dz, TestObserver watch) {
        float cx = ox - mx;                                         // O − M
        float cy = oy - my;
        float cz = oz - mz;
        float a = dx * dx + dy * dy + dz * dz;                      // equation 3.6: R·R
        float b = 2 * (dx * cx + dy * cy + dz * cz);                // equation 3.7: 2·R·(O − M)
        float c = (cx * cx + cy * cy + cz * cz) - r * r;            // equation 3.8: (O − M)·(O − M) − r²
        float discriminant = b * b - 4 * a * c;
        watch.sphere(cx, cy, cz, a, b, c, discriminant);
        return smallestRootNotBehind(a, b, discriminant, watch);
    }

    /**
     * The abc formula: the smaller root {@code (−b − √D) / 2a} if it is {@code ≥ 0}, else the
     * larger one (the ray starts inside the sphere), else NaN (no root, or both behind O).
     */
    private static float smallestRootNotBehind(float a, float b, float discriminant, TestObserver watch) {
        if (!(discriminant >= 0)) {
            return Float.NaN;
        }
        float root = (float) Math.sqrt(discriminant);
        float near = (-b - root) / (2 * a);
        if (near >= 0) {
            watch.roots(root, near, Float.NaN);
            return near;
        }
        float far = (-b + root) / (2 * a);
        watch.roots(root, near, far);
        return far >= 0 ? far : Float.NaN;
    }

    /** {@code (P − M) / r}. */
    @Override
    public Vector3f normalAt(Vector3f point) {
        return point.subtract(center).divide(radius);
    }

    /**
     * The sphere's box, grown by {@code 2e-3·r}: the float test hits a little outside the exact
     * sphere, and the part of that which does not grow with the distance run is at most
     * {@code 1.74e-3·r}.
     */
    @Override
    public BoundingBox bounds() {
        return BoundingBox.around(radius * (1 + 2e-3), center);
    }

    @Override
    public String kind() {
        return "sphere";
    }
}
