package rtd.explain;

import rtd.geometry.RayTriangle;
import rtd.geometry.Triangle;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The intersection test of a triangle explained: where the ray meets the triangle's plane, then
 * on which side of each edge that point lies; the float operations of {@link RayTriangle#hit}.
 */
final class TriangleSteps {

    private static final String[] EDGES = {"p1→p2", "p2→p3", "p3→p1"};

    private TriangleSteps() {
    }

    /** Writes the test into {@code text} and returns its t (NaN: no hit). */
    static float explain(Text text, String head, Triangle triangle, Ray ray) {
        float[] v = triangle.testNumbers();
        Vector3f n = triangle.planeNormal();
        text.hanging(head + "triangle: p1 = " + Numbers.of(triangle.corner(0)) + ", p2 = " + Numbers.of(triangle.corner(1))
                + ", p3 = " + Numbers.of(triangle.corner(2)));
        text.line("n = (p2 − p1) × (p3 − p1) = " + Numbers.of(n));
        float facing = ray.direction().dot(n);
        float t = triangle.corner(0).subtract(ray.origin()).dot(n) / facing;
        text.line("R·n = " + Numbers.of(facing) + ", the plane's t = ((p1 − O)·n) / (R·n) = " + Numbers.of(t));
        if (!(t >= 0) || facing == 0 || Float.isInfinite(t)) {
            text.line(facing == 0 ? "R·n = 0: the ray runs parallel to the plane, no hit"
                    : "the plane lies behind O (or at no finite t), no hit");
            return Float.NaN;
        }
        Vector3f point = ray.pointAt(t);
        text.line("P = O + t·R = " + Numbers.of(point));
        Vector3f d = ray.direction();
        float loose = RayTriangle.looseness(v, 0, point.x(), point.y(), point.z(), d.x(), d.y(), d.z(), t, facing);
        text.line("rounding allowed for P and t: " + Numbers.of(loose) + " (so that a ray through an edge two"
                + " triangles share hits one of them)");
        if (!RayTriangle.nearTheCorners(v, 0, point.x(), point.y(), point.z(), loose)) {
            text.line("P lies beyond the corners' box: no hit");
            return Float.NaN;
        }
        boolean inside = true;
        for (int edge = 0; edge < 3; edge++) {
            float side = RayTriangle.side(v, 0, edge, point.x(), point.y(), point.z());
            float allowance = RayTriangle.allowance(v, 0, edge, point.x(), point.y(), point.z(), loose);
            boolean in = side >= -allowance;
            inside &= in;
            text.line("side of edge " + EDGES[edge] + ": (P − p" + (edge + 1) + ")·(n × edge) = " + Numbers.of(side)
                    + (in ? " ≥ −" + Numbers.of(allowance) + " (its rounding), inside" : " < −" + Numbers.of(allowance)
                            + ", outside"));
        }
        text.line(inside ? "P lies inside the triangle (or on an edge): a hit at t = " + Numbers.of(t)
                : "P lies outside the triangle: no hit");
        return inside ? t : Float.NaN;
    }
}
