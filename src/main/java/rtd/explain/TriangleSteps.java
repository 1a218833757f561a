package rtd.explain;

import rtd.geometry.RayTriangle;
import rtd.geometry.TestObserver;
import rtd.geometry.Triangle;
import rtd.math.Vector3f;

/**
 * The intersection test of a triangle explained: where the ray meets the triangle's plane, then
 * on which side of each edge that point lies; the numbers {@link RayTriangle#hit} tells as it
 * computes them.
 */
final class TriangleSteps implements TestObserver {

    private static final String[] EDGES = {"p1→p2", "p2→p3", "p3→p1"};

    private final Text text;
    private boolean pointFound;
    private boolean outside;

    TriangleSteps(Text text, String head, Triangle triangle) {
        this.text = text;
        text.hanging(head + "triangle: p1 = " + Numbers.of(triangle.corner(0)) + ", p2 = " + Numbers.of(triangle.corner(1))
                + ", p3 = " + Numbers.of(triangle.corner(2)));
        text.line("n = (p2 − p1) × (p3 − p1) = " + Numbers.of(triangle.planeNormal()));
    }

    @Override
    public void plane(float facing, float along, float t) {
        text.line("R·n = " + Numbers.of(facing) + ", the plane's t = ((p1 − O)·n) / (R·n) = " + Numbers.of(t));
        if (!(t >= 0) || facing == 0 || Float.isInfinite(t)) {
            text.line(facing == 0 ? "R·n = 0: the ray runs parallel to the plane, no hit"
                    : "the plane lies behind O (or at no finite t), no hit");
        }
    }

    @Override
    public void trianglePoint(float px, float py, float pz, float loose, boolean nearTheCorners) {
        pointFound = nearTheCorners;
        text.line("P = O + t·R = " + Numbers.of(new Vector3f(px, py, pz)));
        text.line("rounding allowed for P and t: " + Numbers.of(loose) + " (so that a ray through an edge two"
                + " triangles share hits one of them)");
        if (!nearTheCorners) {
            text.line("P lies beyond the corners' box: no hit");
        }
    }

    @Override
    public void triangleSide(int edge, float side, float allowance) {
        boolean in = side >= -allowance;
        outside |= !in;
        text.line("side of edge " + EDGES[edge] + ": (P − p" + (edge + 1) + ")·(n × edge) = " + Numbers.of(side)
                + (in ? " ≥ −" + Numbers.of(allowance) + " (its rounding), inside" : " < −" + Numbers.of(allowance)
                        + ", outside: no hit"));
    }

    /** The verdict on the test's answer {@code t}, once the sides are known. */
    void verdict(float t) {
        if (pointFound && !outside) {
            text.line("P lies inside the triangle (or on an edge): a hit at t = " + Numbers.of(t));
        }
    }
}
