package rtd.geometry;

import java.util.List;
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
     * The sphere's box, widened by how far rounding can move its surface.
     *
     * <p>In {@link #intersect} the discriminant is a difference of two numbers as large as
     * {@code 4|R|²|O − M|²}. Following the standard error bounds of sums and products, the float
     * test hits where an exact test against a sphere of radius {@code r'} would, with
     * {@code r'² ≤ r² + δ} and {@code δ = 15u·D² + 6u·r²} (u the unit roundoff, D = |O − M|;
     * first order, we add a quarter). So the surface moves out by at most
     * {@code min(√δ, δ/2r) + 8u·D}. A hit at t has {@code D ≤ L + r'} with {@code L = t|R|},
     * which bounds that by {@code 1.062e-3·L + 1.74e-3·r} through the root, and by
     * {@code (18.75u/2r)·L² + 2e-6·L + 1e-6·r} through the quotient. The parts that grow with L
     * are the sphere's {@link #rounding}; the rest is grown here, as {@code 2e-3·r}.
     */
    @Override
    public BoundingBox bounds() {
        return BoundingBox.around(radius * (1 + 2e-3), center);
    }

    /** {@link #bounds}, the same numbers, written without making a box. */
    @Override
    public void putBounds(float[] into, int at) {
        BoundingBox.around(radius * (1 + 2e-3), center.x(), center.y(), center.z(), into, at);
    }

    /** {@code 2e-6·L + min(ROUNDING_CONE·L, (18.75u/2r)·L²)}: see {@link #bounds}. */
    @Override
    public Rounding rounding() {
        return new Rounding(2e-6f, (float) (18.75 * 0x1p-24 / (2.0 * radius) * (1 + 1e-3)));
    }

    /** The same shape in the same place, whatever its colour and finish. */
    @Override
    public Object sameTest() {
        return List.of(center, radius);
    }

    @Override
    public String kind() {
        return "sphere";
    }
}
