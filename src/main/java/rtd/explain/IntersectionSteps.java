package rtd.explain;

import java.util.stream.Collectors;
import java.util.stream.IntStream;
import rtd.geometry.Box;
import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.geometry.IGeometry;
import rtd.geometry.Patterned;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.TestObserver;
import rtd.geometry.Transformed;
import rtd.geometry.Triangle;
import rtd.math.Matrix4;
import rtd.math.Ray;

/**
 * Step 2 of an explanation for one object (section 3.2.2): the object's own intersection test, run with this observer,
 * which writes each number the test tells as it computes it: a sphere's (equations 3.5 to 3.8), a plane's, a triangle's
 * plane and edges, a box's slabs, a cylinder's or a cone's side and caps (Part III, "More shapes"), and for a
 * transformed object the ray in the shape's space ({@code M⁻¹O + t·M⁻¹R}, <i>The Ray Tracer Challenge</i>, chapters 4
 * and 14). A kind of object it does not know shows only its test's answer.
 */
final class IntersectionSteps implements TestObserver {

    private static final String[] AXES = {"x", "y", "z"};
    private static final String[] EDGES = {"p1→p2", "p2→p3", "p3→p1"};
    private static final String[] CAPS = {"first cap (at A)", "second cap (at B)"};
    private static final String[] CYLINDER_SIDE = {"R·R − (h·R)²", "2·(w·R − (h·w)(h·R))", "w·w − (h·w)² − r²"};
    private static final String[] CONE_SIDE = {"R·R − (1 + k²)(h·R)²", "2·(w·R − (h·w)(h·R) − k·g·(h·R))",
        "w·w − (h·w)² − g²"};

    private final Text text;
    /** The shape whose test is told: the object, or once the ray is in its space, the shape it transforms. */
    private IGeometry shape;
    private boolean known;
    /** The transformations the ray has been taken through, each indenting the steps of what it holds. */
    private int transforms;
    private float discriminant;
    private float enter = Float.NaN;
    private float exit = Float.NaN;
    private boolean pointFound;
    private boolean outside;

    private IntersectionSteps(Text text) {
        this.text = text;
    }

    /** Runs {@code object}'s test into {@code text}, its first line after {@code head}; returns its t (NaN: no hit). */
    static float explain(Text text, String head, IGeometry object, Ray ray) {
        IntersectionSteps steps = new IntersectionSteps(text);
        steps.start(head, object);
        float t = object.intersect(ray, steps.known ? steps : TestObserver.NONE).t();
        steps.verdict(steps.transforms > 0 ? "" : head, t);
        return t >= 0 ? t : Float.NaN;
    }

    /** The first line of the steps of {@code object} (a pattern's shape's own), if its kind is known. */
    private void start(String head, IGeometry object) {
        shape = object instanceof Patterned patterned ? patterned.shape() : object;
        String first = firstLine();
        known = first != null;
        if (known) {
            text.hanging(head + first);
        }
        if (shape instanceof Triangle triangle) {
            text.line("n = (p2 − p1) × (p3 − p1) = " + Numbers.of(triangle.planeNormal()));
        }
    }

    private String firstLine() {
        if (shape instanceof Transformed t) {
            return t.kind() + ", transformed by M = " + matrix(t.matrix());
        }
        if (shape instanceof Sphere s) {
            return "sphere: M = " + Numbers.of(s.center()) + ", r = " + Numbers.of(s.radius());
        }
        if (shape instanceof Plane p) {
            return "plane: Q = " + Numbers.of(p.point()) + ", n = " + Numbers.of(p.normal());
        }
        if (shape instanceof Triangle t) {
            return "triangle: p1 = " + Numbers.of(t.corner(0)) + ", p2 = " + Numbers.of(t.corner(1)) + ", p3 = "
                    + Numbers.of(t.corner(2));
        }
        if (shape instanceof Box b) {
            return "box: min = " + Numbers.of(b.min()) + ", max = " + Numbers.of(b.max());
        }
        if (shape instanceof Cylinder c) {
            return "cylinder: A = " + Numbers.of(c.first()) + ", B = " + Numbers.of(c.second()) + ", r = "
                    + Numbers.of(c.radius());
        }
        if (shape instanceof Cone c) {
            return "cone: A = " + Numbers.of(c.first()) + ", r1 = " + Numbers.of(c.firstRadius()) + ", B = "
                    + Numbers.of(c.second()) + ", r2 = " + Numbers.of(c.secondRadius())
                    + ", k = (r2 − r1)/|B − A|, g = r1 + k·(h·w)";
        }
        return null;
    }

    /** The last lines of the steps: the test's answer {@code t}, where its steps do not say it, at each depth. */
    private void verdict(String head, float t) {
        if (shape instanceof Box) {
            boxVerdict(t);
        } else if (shape instanceof Triangle && pointFound && !outside) {
            text.line("P lies inside the triangle (or on an edge): a hit at t = " + Numbers.of(t));
        } else if (!known) {
            text.hanging(head + shape.kind() + ": its test gives t = " + Numbers.of(t)
                    + (t >= 0 ? ": a hit" : ": no hit"));
        }
        for (; transforms > 0; transforms--) {
            text.out();
            if (t >= 0) {
                text.line("P = O + t·R on the world's ray, at the same t = " + Numbers.of(t));
            }
        }
    }

    @Override
    public void transformedRay(Matrix4 matrix, Ray objectRay) {
        text.line("the ray in the shape's own space: M⁻¹O = " + Numbers.of(objectRay.origin()) + ", M⁻¹R = "
                + Numbers.of(objectRay.direction()) + " (not normalised: the same t on both rays)");
        text.in();
        transforms++;
        start("", ((Transformed) shape).shape());
    }

    @Override
    public void outsideBox(float t) {
        text.line("but P at t = " + Numbers.of(t) + " lies outside the object's box: float's rounding of a far ray, "
                + "no hit");
    }

    /** The matrix row by row, each entry to 6 decimals at most: [a b c d; …]. */
    static String matrix(Matrix4 m) {
        return "[" + IntStream.range(0, 3).mapToObj(row -> IntStream.range(0, 4).mapToObj(col -> {
            double v = Math.round(m.get(row, col) * 1e6) / 1e6;
            return Numbers.of((float) (v == 0 ? 0 : v));
        }).collect(Collectors.joining(" "))).collect(Collectors.joining("; ")) + "; 0 0 0 1]";
    }

    @Override
    public void sphere(float cx, float cy, float cz, float a, float b, float c, float discriminant) {
        this.discriminant = discriminant;
        text.line("O − M = " + Numbers.of(cx, cy, cz));
        text.line("a = R·R = " + Numbers.of(a) + "   (equation 3.6)");
        text.line("b = 2·R·(O − M) = " + Numbers.of(b) + "   (equation 3.7)");
        text.line("c = (O − M)·(O − M) − r² = " + Numbers.of(c) + "   (equation 3.8)");
        if (!(discriminant >= 0)) {
            text.line("discriminant b² − 4ac = " + Numbers.of(discriminant) + " < 0: no real root, the ray misses");
        }
    }

    @Override
    public void roots(float root, float near, float far) {
        text.line("discriminant b² − 4ac = " + Numbers.of(discriminant) + " ≥ 0, √ = " + Numbers.of(root));
        if (near >= 0) {
            text.line("t = (−b − √)/2a = " + Numbers.of(near) + " ≥ 0: a hit");
        } else if (far >= 0) {
            text.line("t = (−b − √)/2a = " + Numbers.of(near) + " < 0, behind O; t = (−b + √)/2a = " + Numbers.of(far)
                    + " ≥ 0: O is inside, the ray hits the far side");
        } else {
            text.line("t = (−b − √)/2a = " + Numbers.of(near) + " and (−b + √)/2a = " + Numbers.of(far)
                    + ": both roots behind O, no hit");
        }
    }

    /** A plane's test, or a triangle's first step: where the ray meets its plane. */
    @Override
    public void plane(float facing, float along, float t) {
        if (shape instanceof Triangle) {
            text.line("R·n = " + Numbers.of(facing) + ", the plane's t = ((p1 − O)·n) / (R·n) = " + Numbers.of(t));
            if (!(t >= 0) || facing == 0 || Float.isInfinite(t)) {
                text.line(facing == 0 ? "R·n = 0: the ray runs parallel to the plane, no hit"
                        : "the plane lies behind O (or at no finite t), no hit");
            }
            return;
        }
        text.line("R·n = " + Numbers.of(facing));
        if (facing == 0) {
            text.line("R·n = 0: the ray runs parallel to the plane, no hit");
            return;
        }
        String verdict = t == Float.POSITIVE_INFINITY
                ? ": the ray runs so nearly parallel that it never meets it, no hit"
                : t >= 0 ? " ≥ 0: a hit" : ": the plane lies behind O, no hit";
        text.line("t = ((Q − O)·n) / (R·n) = " + Numbers.of(along) + " / " + Numbers.of(facing) + " = " + Numbers.of(t)
                + verdict);
    }

    @Override
    public void trianglePoint(float px, float py, float pz, float loose, boolean nearTheCorners) {
        pointFound = nearTheCorners;
        text.line("P = O + t·R = " + Numbers.of(px, py, pz));
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

    @Override
    public void parallelSlab(int axis, boolean outside) {
        text.line(AXES[axis] + ": R" + AXES[axis] + " = 0, the ray runs parallel to the slab and is "
                + (outside ? "outside it: no hit" : "inside it everywhere"));
    }

    @Override
    public void slab(int axis, float t0, float t1) {
        String low = "(min − O)/R = ";
        String high = "(max − O)/R = ";
        text.line(AXES[axis] + ": t from " + (t0 <= t1 ? low + Numbers.of(t0) + " to " + high + Numbers.of(t1)
                : high + Numbers.of(t1) + " to " + low + Numbers.of(t0)));
    }

    @Override
    public void slabs(float enter, float exit) {
        this.enter = enter;
        this.exit = exit;
        text.line("in all three slabs: t from " + Numbers.of(enter) + " (enter, the largest start) to "
                + Numbers.of(exit) + " (exit, the smallest end)");
    }

    private void boxVerdict(float t) {
        if (Float.isNaN(enter)) {
            return; // a parallel slab the ray is outside of: already said
        }
        if (enter > exit || exit < 0) {
            text.line(enter > exit ? "enter > exit: the intervals do not overlap, no hit"
                    : "exit < 0: the box lies behind O, no hit");
        } else if (!(t >= 0)) {
            text.line("t = " + Numbers.of(enter >= 0 ? enter : exit)
                    + " is not finite: the ray's direction is too short to reach the box, no hit");
        } else {
            String which = enter >= 0 ? "t = enter = " : "enter < 0: O is inside, t = exit = ";
            text.line(which + Numbers.of(t) + ": a hit");
        }
    }

    /** A cylinder's or a cone's side: its quadratic, with the coefficients as that shape's {@code hit} writes them. */
    @Override
    public void side(float t0, float a, float b, float c, float discriminant) {
        String[] formulas = shape instanceof Cone ? CONE_SIDE : CYLINDER_SIDE;
        text.line("side, from O' = O + t0·R nearest the axis's middle M, t0 = (M − O)·R/(R·R) = " + Numbers.of(t0)
                + ":");
        text.line("  a·t'² + b·t' + c = 0 with w = O' − A, h the unit axis, and t = t0 + t'");
        text.line("  a = " + formulas[0] + " = " + Numbers.of(a));
        text.line("  b = " + formulas[1] + " = " + Numbers.of(b));
        text.line("  c = " + formulas[2] + " = " + Numbers.of(c));
        text.line("  discriminant b² − 4ac = " + Numbers.of(discriminant)
                + (a == 0 ? ", a = 0: one root, −c/b" : discriminant >= 0 ? " ≥ 0" : " < 0: the ray misses the side"));
    }

    @Override
    public void sideRoot(float t, float along, boolean between) {
        text.line("  root t = t0 + t' = " + Numbers.of(t) + ": s = h·(P − A) = " + Numbers.of(along)
                + (between ? ", between the ends" : ", beyond an end: not on the side"));
    }

    @Override
    public void cap(int end, float t, float fromCentreSquared, float radiusSquared) {
        if (Float.isNaN(t)) {
            text.line(CAPS[end] + ": the ray runs parallel to its plane or meets it behind O");
            return;
        }
        boolean on = fromCentreSquared <= radiusSquared;
        text.line(CAPS[end] + ": its plane at t = " + Numbers.of(t) + ", |P − " + (end == 0 ? "A" : "B") + "|² = "
                + Numbers.of(fromCentreSquared) + (on ? " ≤ " : " > ") + "r² = " + Numbers.of(radiusSquared)
                + (on ? ": on the cap" : ": beside the cap"));
    }

    @Override
    public void nearestPart(String part, float t) {
        text.line(part.equals("none") ? "no part is hit at t ≥ 0: no hit"
                : "nearest: t = " + Numbers.of(t) + " on the " + part + ": a hit");
    }
}
