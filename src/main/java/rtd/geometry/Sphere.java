package rtd.geometry;

import rtd.camera.ICamera;
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
        return Intersection.at(ray, smallestRootNotBehind(a, b, b * b - 4 * a * c));
    }

    /**
     * The abc formula: the smaller root {@code (−b − √D) / 2a} if it is {@code ≥ 0}, else the
     * larger one (the ray starts inside the sphere), else NaN (no root, or both behind O).
     * Public for the BVH's packed test of the same equations.
     */
    public static float smallestRootNotBehind(float a, float b, float discriminant) {
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
     * <p>In {@link #intersect} the discriminant is a difference of two numbers as large as
     * {@code 4|R|²|O − M|²}. Following the standard error bounds of sums and products, each
     * rounding changes it by so little that the float test hits exactly where an exact test
     * against a sphere of radius {@code r'} would, with {@code r'² ≤ r² + δ} and
     * {@code δ = 15u·|O − M|² + 6u·r²} (u the unit roundoff; first order, we add a quarter).
     * So the surface moves out by at most {@code min(√δ, δ / 2r)}, plus a few u·|O − M| for
     * the rounding of b and of the root. {@code |O − M|} is at most what the camera says for
     * rays that pass close enough to hit.
     */
    @Override
    public BoundingBox bounds(ICamera camera) {
        double slack = 0;
        for (int round = 0; round < 2; round++) { // the reach grows with the slack: settle it
            double d = camera.farthestOrigin(center, (float) (radius + slack + 1e-3 * radius));
            double delta = 1.25 * (15 * UNIT_ROUNDOFF * d * d + 6 * UNIT_ROUNDOFF * (double) radius * radius);
            slack = Math.min(Math.sqrt(delta), delta / (2.0 * radius)) + 8 * UNIT_ROUNDOFF * d;
        }
        double half = (radius + slack) * (1 + 1e-6) + 4 * UNIT_ROUNDOFF * maxAbs(center);
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
