package rtd.pov;

import static rtd.pov.PovNumbers.num;

import java.util.stream.Stream;
import rtd.geometry.BoundingBox;
import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Pattern;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.math.Matrix4;
import rtd.math.Vector3f;

/**
 * Patterns and transformations in POV-Ray's words, for {@link PovScene}. A transformation is POV-Ray's
 * {@code matrix <…>}, M's twelve numbers column by column (POV-Ray multiplies row vectors), written after the pigment
 * so that it moves the pattern with the object, as rtd does. A pattern is a {@code function} pattern that draws rtd's
 * rule exactly: POV-Ray's own {@code checker} looks at the hit point P, rtd at {@code P − ε·N} just beneath the surface
 * (a floor at y = 0 would swap its colours), and its {@code onion} is spherical where rtd's rings are about the y axis.
 * So the function moves the point into the shape as rtd's {@code under} does (along a plane's or a triangle's normal,
 * towards a sphere's centre, into a box), takes it into the pattern's space and applies the rule. POV-Ray blends a
 * gradient where rtd rounds each channel: at most half a level apart.
 */
final class PovPaint {

    private PovPaint() {
    }

    /** {@code matrix <…>} of M: POV-Ray's twelve numbers, row by row of Mᵀ. */
    static String matrix(Matrix4 m) {
        StringBuilder text = new StringBuilder("matrix <");
        for (int row = 0; row < 4; row++) {
            for (int col = 0; col < 3; col++) {
                text.append(row + col > 0 ? ", " : "").append(num(m.get(col, row)));
            }
        }
        return text.append('>').toString();
    }

    /**
     * The pigment of {@code shape} in {@code pattern}'s colours;
     * {@code filter} is the rgbt share let through (0: none).
     */
    static String pigment(IGeometry shape, Pattern pattern, float filter) {
        String[] p = under(shape);
        Matrix4 inverse = pattern.transform().inverse();
        String[] q = new String[3];
        for (int row = 0; row < 3; row++) {
            q[row] = "(" + num(inverse.get(row, 0)) + "*" + p[0] + " + " + num(inverse.get(row, 1)) + "*" + p[1] + " + "
                    + num(inverse.get(row, 2)) + "*" + p[2] + " + " + num(inverse.get(row, 3)) + ")";
        }
        String a = colour(pattern.a().red(), pattern.a().green(), pattern.a().blue(), filter);
        String b = colour(pattern.b().red(), pattern.b().green(), pattern.b().blue(), filter);
        String rule = switch (pattern.kind()) {
            case STRIPES -> "0.5*abs(mod(floor(" + q[0] + "), 2))";
            case CHECKER -> "0.5*abs(mod(floor(" + q[0] + ") + floor(" + q[1] + ") + floor(" + q[2] + "), 2))";
            case RINGS -> "0.5*abs(mod(floor(sqrt(" + q[0] + "*" + q[0] + " + " + q[2] + "*" + q[2] + ")), 2))";
            case GRADIENT -> q[0] + " - floor(" + q[0] + ")";
        };
        String map = pattern.kind() == Pattern.Kind.GRADIENT ? "[0 " + a + "] [1 " + b + "]"
                : "[0.25 " + a + "] [0.25 " + b + "]";
        return "pigment { function { " + rule + " } color_map { " + map + " } }";
    }

    /** The point x, y, z moved a little into {@code shape}, as three expressions: rtd's {@code P − ε·N}. */
    private static String[] under(IGeometry shape) {
        double lift = 1e-4 * (1 + largest(shape));
        if (shape instanceof Plane plane) {
            return along(plane.normal().normalize(), lift);
        }
        if (shape instanceof Triangle triangle) {
            return along(triangle.planeNormal().normalize(), lift);
        }
        if (shape instanceof Sphere sphere) {
            Vector3f c = sphere.center();
            double k = 1 - lift / sphere.radius();
            return new String[] {"(" + num(c.x()) + " + (x - " + num(c.x()) + ")*" + num(k) + ")",
                "(" + num(c.y()) + " + (y - " + num(c.y()) + ")*" + num(k) + ")",
                "(" + num(c.z()) + " + (z - " + num(c.z()) + ")*" + num(k) + ")"};
        }
        if (shape instanceof Box box) {
            return new String[] {clamp("x", box.min().x(), box.max().x(), lift),
                clamp("y", box.min().y(), box.max().y(), lift),
                clamp("z", box.min().z(), box.max().z(), lift)};
        }
        return new String[] {"x", "y", "z"};
    }

    private static String[] along(Vector3f n, double lift) {
        return new String[] {"(x - " + num(lift * n.x()) + ")", "(y - " + num(lift * n.y()) + ")",
            "(z - " + num(lift * n.z()) + ")"};
    }

    private static String clamp(String axis, float low, float high, double lift) {
        return "min(max(" + axis + ", " + num(low + lift) + "), " + num(high - lift) + ")";
    }

    /** The largest coordinate of the shape's box (or of a plane's point): how large its ε is. */
    private static double largest(IGeometry shape) {
        BoundingBox box = shape.bounds();
        Stream<Vector3f> corners = shape instanceof Plane plane ? Stream.of(plane.point())
                : box.isBounded() ? Stream.of(box.min(), box.max()) : Stream.empty();
        return corners.mapToDouble(c -> Math.max(Math.abs(c.x()), Math.max(Math.abs(c.y()), Math.abs(c.z())))).max()
                .orElse(0);
    }

    private static String colour(int r, int g, int b, float filter) {
        String rgb = num(r / 255f) + ", " + num(g / 255f) + ", " + num(b / 255f);
        return filter > 0 ? "rgbt <" + rgb + ", " + num(filter) + ">" : "rgb <" + rgb + ">";
    }

}
