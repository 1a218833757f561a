package rtd.geometry;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A solid cylinder of radius r whose axis runs from the end point A to the end point B, closed by
 * two flat caps (Part III, "More shapes"; <i>The Ray Tracer Challenge</i>, chapter 13, with the
 * axis anywhere). A ray that starts inside hits it from within, as POV-Ray's {@code cylinder}.
 *
 * @param first  the end point A, the centre of the first cap
 * @param second the end point B, the centre of the second cap (not A)
 * @param radius r, greater than 0
 */
public record Cylinder(Vector3f first, Vector3f second, float radius, Color color, Material material)
        implements IGeometry {

    /** The nearest hit of the side and the two caps ({@link #hit}). */
    @Override
    public Intersection intersect(Ray ray) {
        return intersect(ray, TestObserver.NONE);
    }

    @Override
    public Intersection intersect(Ray ray, TestObserver watch) {
        Vector3f o = ray.origin();
        Vector3f d = ray.direction();
        return Intersection.at(ray, hit(first.x(), first.y(), first.z(), second.x(), second.y(), second.z(), radius,
                o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), watch));
    }

    /**
     * The test of the ray O + t·R against the cylinder from A to B of radius r. The side is solved
     * from the ray's point {@code O' = O + t0·R} nearest the axis's middle
     * ({@link SideRoots#nearestTheMiddle}), {@code t = t0 + t'}. With the unit axis
     * {@code h = (B − A)/|B − A|} and {@code w = O' − A}, the point {@code q = w + t'·R} (P − A)
     * lies {@code s = h·q} along the axis and {@code √(q·q − s²)} from it. The side is where that
     * distance is r:
     * <pre>
     *   q·q − (h·q)² = r²   ⇔   a·t'² + b·t' + c = 0  with
     *   a = R·R − (h·R)²,   b = 2·(w·R − (h·w)(h·R)),   c = w·w − (h·w)² − r²
     * </pre>
     * and each root counts ({@link SideRoots}) where {@code 0 ≤ s ≤ |B − A|}, between the caps.
     * Each cap is a plane at right angles to h through its end point, hit within r of it
     * ({@link Disc}). Returns the
     * smallest t ≥ 0 of the side and the caps, or NaN. Every renderer runs this test.
     */
    public static float hit(float ax, float ay, float az, float bx, float by, float bz, float r,
            float ox, float oy, float oz, float dx, float dy, float dz, TestObserver watch) {
        float length = (float) Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay) + (bz - az) * (bz - az));
        float hx = (bx - ax) / length;                        // h = (B − A)/|B − A|
        float hy = (by - ay) / length;
        float hz = (bz - az) / length;
        float t0 = SideRoots.nearestTheMiddle(ax, ay, az, bx, by, bz, ox, oy, oz, dx, dy, dz);
        float wx = (ox + t0 * dx) - ax;                       // w = O' − A, O' = O + t0·R
        float wy = (oy + t0 * dy) - ay;
        float wz = (oz + t0 * dz) - az;
        float hd = hx * dx + hy * dy + hz * dz;               // h·R
        float hw = hx * wx + hy * wy + hz * wz;               // h·w
        float a = (dx * dx + dy * dy + dz * dz) - hd * hd;    // R·R − (h·R)²
        float b = 2 * ((wx * dx + wy * dy + wz * dz) - hw * hd); // 2·(w·R − (h·w)(h·R))
        float c = (wx * wx + wy * wy + wz * wz) - hw * hw - r * r; // w·w − (h·w)² − r²
        float side = SideRoots.nearest(t0, a, b, c, hw, hd, length, watch);
        return Disc.nearestWithCaps(side, ax, ay, az, r, bx, by, bz, r, hx, hy, hz, ox, oy, oz, dx, dy, dz, watch);
    }

    /**
     * The outward normal of the part {@code point} lies nearest to: a cap's is along the axis
     * ({@code −h} at A, {@code h} at B), the side's points from the axis outwards.
     */
    @Override
    public Vector3f normalAt(Vector3f point) {
        Vector3f axis = second.subtract(first);
        float length = axis.magnitude();
        Vector3f h = axis.divide(length);
        Vector3f q = point.subtract(first);
        float s = h.dot(q);
        Vector3f fromAxis = q.subtract(h.multiply(s));
        float distance = fromAxis.magnitude();
        float toSide = Math.abs(distance - radius);
        if (Math.abs(s) < toSide && Math.abs(s) <= Math.abs(length - s)) {
            return Vector3f.ZERO.subtract(h); // −h, with +0 rather than −0
        }
        if (Math.abs(length - s) < toSide) {
            return h;
        }
        return fromAxis.divide(distance);
    }

    /**
     * The box around both end points grown by the radius (every point of the cylinder lies
     * within r of its axis), and by {@code 2e-3} of the radius and of the length: the float test
     * hits a little outside the exact solid, as a sphere's does ({@link Sphere#bounds}).
     */
    @Override
    public BoundingBox bounds() {
        return BoundingBox.around(radius * (1 + 2e-3) + 2e-3 * second.subtract(first).magnitude(), first, second);
    }

    @Override
    public String kind() {
        return "cylinder";
    }
}
