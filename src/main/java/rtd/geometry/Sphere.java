package rtd.geometry;

import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Color;

/**
 * A sphere with a centre M, a radius r and one flat colour (paper, sections 3.2.2 and 4.2.2).
 *
 * <p>{@link #intersect} solves the quadratic equation 3.5 in single precision, exactly in the
 * order of equations 3.6 to 3.8, so that it draws what the paper's program draws.
 */
public record Sphere(Vector3f center, float radius, Color color) implements IGeometry {

    /** Unit roundoff of {@code float}: the largest relative error of one rounding. */
    private static final float UNIT_ROUNDOFF = 0x1p-24f;

    /**
     * Solves {@code a·t² + b·t + c = 0} (equation 3.5) and returns the smallest root
     * {@code t ≥ 0}: the nearer hit, or the far one when the ray starts inside the sphere.
     */
    @Override
    public Intersection intersect(Ray ray) {
        Vector3f direction = ray.direction();
        Vector3f centerToOrigin = ray.origin().subtract(center);            // O − M
        float a = direction.dot(direction);                                  // equation 3.6
        float b = 2 * direction.dot(centerToOrigin);                        // equation 3.7
        float c = centerToOrigin.dot(centerToOrigin) - radius * radius;      // equation 3.8
        float t = smallestRootNotBehind(a, b, b * b - 4 * a * c);
        // One return of one new object, hit or miss: the JIT can then keep it in registers.
        return new Intersection(t >= 0, t, ray.pointAt(t));
    }

    /**
     * The abc formula: the smaller root {@code (−b − √D) / 2a} if it is {@code ≥ 0}, else the
     * larger one (the ray starts inside the sphere), else NaN (no root, or both behind O).
     */
    private static float smallestRootNotBehind(float a, float b, float discriminant) {
        if (!(discriminant >= 0)) {
            return Float.NaN;
        }
        float root = (float) Math.sqrt(discriminant);
        float near = (-b - root) / (2 * a);
        if (near >= 0) {
            return near;
        }
        float far = (-b + root) / (2 * a);
        return far >= 0 ? far : Float.NaN;
    }

    /**
     * The sphere's box, widened by how far rounding can move its surface.
     *
     * <p>In {@link #intersect} the discriminant is a difference of numbers as large as
     * {@code |O − M|²}; its rounding error amounts to testing against a sphere of radius
     * {@code r'} with {@code r'² ≤ r² + δ}, {@code δ = 16u·|O − M|² + 6u·r²} (u the unit roundoff,
     * by the standard error bounds of dot products). We widen by four times that: the surface
     * moves by at most {@code min(√δ, δ / 2r)}.
     */
    @Override
    public BoundingBox bounds(Vector3f originCentre, float originRadius) {
        double d = (double) originCentre.subtract(center).magnitude() + originRadius + radius; // ≥ |O − M|
        double delta = 4 * (16 * UNIT_ROUNDOFF * d * d + 6 * UNIT_ROUNDOFF * (double) radius * radius);
        double slack = Math.min(Math.sqrt(delta), delta / (2.0 * radius)) + 4 * UNIT_ROUNDOFF * d;
        double half = radius + slack + 4 * UNIT_ROUNDOFF * (Math.abs(radius) + maxAbs(center));
        return new BoundingBox(
                new Vector3f(down(center.x() - half), down(center.y() - half), down(center.z() - half)),
                new Vector3f(up(center.x() + half), up(center.y() + half), up(center.z() + half)));
    }

    private static float maxAbs(Vector3f v) {
        return Math.max(Math.abs(v.x()), Math.max(Math.abs(v.y()), Math.abs(v.z())));
    }

    private static float down(double value) {
        return Math.nextDown((float) value);
    }

    private static float up(double value) {
        return Math.nextUp((float) value);
    }
}
