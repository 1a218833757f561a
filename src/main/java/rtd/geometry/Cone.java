package rtd.geometry;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A solid truncated cone from the end point A, where its radius is r1, to the end point B, where
 * it is r2, closed by two flat caps (Part III, "More shapes"; <i>The Ray Tracer Challenge</i>,
 * chapter 13, with the axis anywhere). A radius may be 0, not both: that cap is the apex, a point.
 * A ray that starts inside hits it from within, as POV-Ray's {@code cone}.
 *
 * @param first        the end point A
 * @param firstRadius  r1, the radius at A, at least 0
 * @param second       the end point B (not A)
 * @param secondRadius r2, the radius at B, at least 0
 */
public record Cone(Vector3f first, float firstRadius, Vector3f second, float secondRadius, Color color,
        Material material) implements IGeometry {

    /** The nearest hit of the side and the two caps ({@link #hit}). */
    @Override
    public Intersection intersect(Ray ray) {
        return intersect(ray, TestObserver.NONE);
    }

    @Override
    public Intersection intersect(Ray ray, TestObserver watch) {
        Vector3f o = ray.origin();
        Vector3f d = ray.direction();
        return Intersection.at(ray, hit(first.x(), first.y(), first.z(), firstRadius,
                second.x(), second.y(), second.z(),
                secondRadius, o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), watch));
    }

    /**
     * The test of the ray O + t·R against the cone from A (radius r1) to B (radius r2). The side
     * is solved from the ray's point {@code O' = O + t0·R} nearest the axis's middle
     * ({@link SideRoots#nearestTheMiddle}), {@code t = t0 + t'}. With the unit axis
     * {@code h = (B − A)/|B − A|}, {@code w = O' − A} and the slope {@code k = (r2 − r1)/|B − A|},
     * the point {@code q = w + t'·R} (P − A) lies {@code s = h·q} along the axis, where the side's
     * radius is {@code r1 + k·s}, and {@code √(q·q − s²)} from the axis. The side is where the two
     * are equal; with {@code g = r1 + k·(h·w)}, the radius level with O':
     * <pre>
     *   q·q − (h·q)² = (r1 + k·h·q)²   ⇔   a·t'² + b·t' + c = 0  with
     *   a = R·R − (1 + k²)(h·R)²,   b = 2·(w·R − (h·w)(h·R) − k·g·(h·R)),   c = w·w − (h·w)² − g²
     * </pre>
     * and each root counts ({@link SideRoots}) where {@code 0 ≤ s ≤ |B − A|}, between the caps
     * (the cone's mirror image beyond its apex lies outside). Each cap is a plane at right angles
     * to h through its end point, hit within its radius of it ({@link Disc}). Returns the
     * smallest t ≥ 0 of the side and the caps, or NaN. Every renderer runs this test.
     */
    public static float hit(float ax, float ay, float az, float r1, float bx, float by, float bz, float r2,
            float ox, float oy, float oz, float dx, float dy, float dz, TestObserver watch) {
        float length = (float) Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay) + (bz - az) * (bz - az));
        float hx = (bx - ax) / length;                        // h = (B − A)/|B − A|
        float hy = (by - ay) / length;
        float hz = (bz - az) / length;
        float k = (r2 - r1) / length;                         // the slope: radius gained per unit along h
        float t0 = SideRoots.nearestTheMiddle(ax, ay, az, bx, by, bz, ox, oy, oz, dx, dy, dz);
        float wx = (ox + t0 * dx) - ax;                       // w = O' − A, O' = O + t0·R
        float wy = (oy + t0 * dy) - ay;
        float wz = (oz + t0 * dz) - az;
        float hd = hx * dx + hy * dy + hz * dz;               // h·R
        float hw = hx * wx + hy * wy + hz * wz;               // h·w
        float g = r1 + k * hw;                                // the radius level with O'
        float a = (dx * dx + dy * dy + dz * dz) - (1 + k * k) * (hd * hd);  // R·R − (1 + k²)(h·R)²
        float b = 2 * ((wx * dx + wy * dy + wz * dz) - hw * hd - k * g * hd); // 2·(w·R − (h·w)(h·R) − k·g·(h·R))
        float c = (wx * wx + wy * wy + wz * wz) - hw * hw - g * g;          // w·w − (h·w)² − g²
        float side = SideRoots.nearest(t0, a, b, c, hw, hd, length, watch);
        return Disc.nearestWithCaps(side, ax, ay, az, r1, bx, by, bz, r2, hx, hy, hz, ox, oy, oz, dx, dy, dz, watch);
    }

    /**
     * The outward normal of the part {@code point} lies nearest to: a cap's is along the axis
     * ({@code −h} at A, {@code h} at B); the side's is at right angles to the slanted surface,
     * {@code (e − k·h)/√(1 + k²)} with e the unit vector from the axis to the point. At an apex
     * the cap's (a point) is taken.
     */
    @Override
    public Vector3f normalAt(Vector3f point) {
        Vector3f axis = second.subtract(first);
        float length = axis.magnitude();
        Vector3f h = axis.divide(length);
        float k = (secondRadius - firstRadius) / length;
        Vector3f q = point.subtract(first);
        float s = h.dot(q);
        Vector3f fromAxis = q.subtract(h.multiply(s));
        float slant = (float) Math.sqrt(1 + k * k);
        float toSide = Math.abs(fromAxis.magnitude() - (firstRadius + k * s)) / slant;
        if (Math.abs(s) <= toSide && Math.abs(s) <= Math.abs(length - s)) {
            return Vector3f.ZERO.subtract(h); // −h, with +0 rather than −0
        }
        if (Math.abs(length - s) <= toSide) {
            return h;
        }
        return fromAxis.normalize().subtract(h.multiply(k)).divide(slant);
    }

    /**
     * The box around both end points grown by the larger radius (every point of the cone lies
     * within it of its axis), and by {@code 2e-3} of that radius and of the length: the float test
     * hits a little outside the exact solid, as a sphere's does ({@link Sphere#bounds}).
     */
    @Override
    public BoundingBox bounds() {
        float r = Math.max(firstRadius, secondRadius);
        return BoundingBox.around(r * (1 + 2e-3) + 2e-3 * second.subtract(first).magnitude(), first, second);
    }

    @Override
    public String kind() {
        return "cone";
    }
}
