package rtd.io;

import static rtd.io.Group.numbers;
import static rtd.io.Group.word;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Rgb;
import rtd.io.Group.Rule;
import rtd.math.Vector3f;
import rtd.scene.AreaLight;
import rtd.scene.Light;

/**
 * The scene grammar: every statement, declared once with its keyword, its groups with their rules, and how it
 * builds its value (the paper's, section 4.1; Part II's, "The scene file"). To add a statement, add one entry
 * to {@link #STATEMENTS}: the reader, the checks of its values and the messages (the usage, the keyword list,
 * "did you mean …?") follow from it.
 */
final class Grammar {

    private static final float FLOOR_RADIUS = 5000;
    static final String LET = "let";
    private static final Group NAME = word("name", Rule.NAME, "name");
    private static final Group POSITION = numbers("position", "x|y|z");
    private static final Group VIEW = new Group("view direction", Rule.VIEW, "x|y|z", 3,
            "the camera looks along it; (0|0|-1) looks into the screen");
    private static final Group PAINT = numbers("colour", Rule.PAINT, "R|G|B");
    private static final Group FIRST_CORNER = numbers("first corner", "x1|y1|z1");
    private static final Group SECOND_CORNER = numbers("second corner", "x2|y2|z2");
    private static final Group FIRST_END = numbers("first end", "x1|y1|z1");
    private static final Group SECOND_END = numbers("second end", "x2|y2|z2");

    /** Every statement, in the order the messages list them. */
    static final List<Statement> STATEMENTS = List.of(
            Statement.setting("ambient", List.of(numbers("colour", Rule.COLOUR, "R|G|B")),
                    (v, out) -> out.ambient(v.colour(0))),
            Statement.setting("orthographic_camera", List.of(POSITION, VIEW, numbers("zoom", Rule.POSITIVE, "zoom")),
                    (v, out) -> out.camera(v.target == 1 ? OrthographicCamera.lookingAt(v.vector(0), v.vector(1),
                            v.number(2, 0)) : new OrthographicCamera(v.vector(0), v.vector(1), v.number(2, 0)))),
            Statement.setting("perspective_camera",
                    List.of(POSITION, VIEW, numbers("field of view", Rule.ANGLE, "fov")),
                    (v, out) -> out.camera(v.target == 1 ? PerspectiveCamera.lookingAt(v.vector(0), v.vector(1),
                            v.number(2, 0)) : new PerspectiveCamera(v.vector(0), v.vector(1), v.number(2, 0)))),
            Statement.shape("sphere", List.of(numbers("centre", "x|y|z"), numbers("radius", Rule.POSITIVE, "r"), PAINT),
                    (v, out) -> out.object(sphere(v, out))),
            Statement.shape("plane", List.of(numbers("point", "x|y|z"), new Group("normal", Rule.DIRECTION, "nx|ny|nz",
                    3, "the plane is at right angles to it; (0|1|0) makes a floor"), PAINT),
                    (v, out) -> out.object(new Plane(v.vector(0), v.vector(1), v.colour(2), v.material()))),
            Statement.shape("triangle",
                    List.of(FIRST_CORNER, SECOND_CORNER, numbers("third corner", "x3|y3|z3"), PAINT),
                    (v, out) -> out.object(triangle(v))),
            Statement.shape("box", List.of(FIRST_CORNER, SECOND_CORNER, PAINT), (v, out) -> out.object(box(v))),
            Statement.shape("mesh", List.of(word("file", Rule.PATH, "path"), numbers("shift", "x|y|z"),
                    numbers("scale", Rule.POSITIVE, "s"), PAINT), (v, out) -> out.objects(ObjMesh.read(v, 0)
                            .triangles(v.vector(1), v.number(2, 0), v.colour(3), v.material()))),
            Statement.setting("light", List.of(POSITION, numbers("intensity", Rule.COLOUR, "R|G|B")),
                    (v, out) -> out.light(new Light(v.vector(0), Rgb.of(v.colour(1))))),
            Statement.setting("material", List.of(NAME, word("properties", Rule.PROPERTIES, "key=value|key=value...")),
                    (v, out) -> out.define(v.name(0), "material", material(v), null)),
            Statement.shape("cylinder", List.of(FIRST_END, SECOND_END, numbers("radius", Rule.POSITIVE, "r"), PAINT),
                    (v, out) -> out.object(cylinder(v))),
            Statement.shape("cone", List.of(FIRST_END, numbers("first radius", Rule.AT_LEAST_ZERO, "r1"),
                    SECOND_END, numbers("second radius", Rule.AT_LEAST_ZERO, "r2"), PAINT),
                    (v, out) -> out.object(cone(v))),
            Statement.setting("area_light", List.of(numbers("corner", "x|y|z"), numbers("first edge", "ux|uy|uz"),
                    numbers("second edge", "vx|vy|vz"), numbers("samples", Rule.SAMPLES, "n|m"),
                    numbers("intensity", Rule.COLOUR, "R|G|B")), (v, out) -> new AreaLight(v.vector(0), v.vector(1),
                            v.vector(2), (int) v.number(3, 0), (int) v.number(3, 1), Rgb.of(v.colour(4)))
                            .samples().forEach(out::light)),
            new Statement("pattern", List.of(NAME, word("kind", Rule.NAME, "stripes|gradient|rings|checker"),
                    numbers("first colour", Rule.COLOUR, "R|G|B"), numbers("second colour", Rule.COLOUR, "R|G|B")),
                    List.of(Statement.TRANSFORM), false, Names::pattern),
            new Statement("transform", List.of(NAME, word("step", Rule.STEP, "scale s")),
                    List.of(word("step", Rule.STEP, "step")), true, Names::transform),
            Statement.setting(LET, List.of(NAME, numbers("value", "expression")), (v, out) -> Names.let(v)));

    /** A {@code material}'s finish: each property given, or the default's. */
    private static Material material(StatementValues v) {
        Material d = Material.DEFAULT;
        float[] p = {d.ambient(), d.diffuse(), d.specular(), d.shininess(), d.reflective(), d.transparency(), d.ior()};
        for (int k = 0; k < v.size(1); k++) {
            p[v.key(1, k)] = v.number(1, k);
        }
        return new Material(p[0], p[1], p[2], p[3], p[4], p[5], p[6]);
    }

    /** The keywords as bytes, beside {@link #STATEMENTS}, to find a line's statement without a String. */
    private static final byte[][] KEYWORDS = STATEMENTS.stream()
            .map(s -> s.keyword().getBytes(StandardCharsets.US_ASCII)).toArray(byte[][]::new);

    private Grammar() {
    }

    static Statement find(byte[] bytes, int start, int end) {
        for (int k = 0; k < KEYWORDS.length; k++) { // no Iterator for each line of a large file
            if (Arrays.equals(KEYWORDS[k], 0, KEYWORDS[k].length, bytes, start, end)) {
                return STATEMENTS.get(k);
            }
        }
        return null;
    }

    /** All keywords, for messages: "'ambient', 'orthographic_camera', … or 'material'". */
    static String keywordList() {
        return Hints.quoted(STATEMENTS.stream().map(Statement::keyword).toList(), "or");
    }

    /**
     * A sphere; one of radius {@value #FLOOR_RADIUS} or more warns in a shaded scene: float rounds its hit points
     * by more than a shadow ray's lift, so it shows acne (<i>Ray Tracing in One Weekend</i>'s 1000 draws clean).
     */
    private static Sphere sphere(StatementValues v, SceneContents out) {
        Sphere sphere = new Sphere(v.vector(0), v.number(1, 0), v.colour(2), v.material());
        if (sphere.radius() >= FLOOR_RADIUS) {
            out.litWarnings.add(v.errorAtValue(1, 0, "a sphere of radius " + v.written(1, 0) + " may show shadow acne, "
                    + "dark speckles where it is lit: float is too coarse on a surface that large",
                    "for a floor or a wall, use a plane: plane:(0|0|0):(0|1|0):(200|200|200) is a floor at "
                    + "y = 0").place);
        }
        return sphere;
    }

    /** A triangle whose corners do not lie on one line (else it has no area and is never hit). */
    private static Triangle triangle(StatementValues v) throws SceneException {
        Vector3f p1 = v.vector(0);
        Vector3f n = v.vector(1).subtract(p1).cross(v.vector(2).subtract(p1)); // as the triangle computes it
        if (n.x() == 0 && n.y() == 0 && n.z() == 0) {
            throw v.errorAtGroup(0, "the corners of the triangle lie on one line, so it has no area",
                    "three corners that do not lie on one line make a triangle, such as (0|0|0), (1|0|0) and (0|1|0)");
        }
        if (!n.isFinite()) {
            throw v.errorAtGroup(0, "the triangle is too large to compute with in float",
                    "its sides must be shorter than about 1e19");
        }
        return new Triangle(p1, v.vector(1), v.vector(2), v.colour(3), v.material());
    }

    /** A box whose corners differ in every coordinate (else it is flat). */
    private static Box box(StatementValues v) throws SceneException {
        for (int k = 0; k < 3; k++) {
            if (v.number(0, k) == v.number(1, k)) {
                throw v.errorAtValue(1, k, "the box is flat: both corners have " + "xyz".charAt(k) + " = "
                        + v.written(1, k), "a box takes two opposite corners, which differ in x, y and z");
            }
        }
        return Box.between(v.vector(0), v.vector(1), v.colour(2), v.material());
    }

    /** A cylinder between two different end points (Part III, "More shapes"). */
    private static Cylinder cylinder(StatementValues v) throws SceneException {
        axis(v, 1, "cylinder", "a cylinder runs from one end point to another, such as (0|0|0) to (0|2|0)");
        return new Cylinder(v.vector(0), v.vector(1), v.number(2, 0), v.colour(3), v.material());
    }

    /** A cone whose radii are not both 0, between two different end points (Part III, "More shapes"). */
    private static Cone cone(StatementValues v) throws SceneException {
        if (v.number(1, 0) == 0 && v.number(3, 0) == 0) {
            throw v.errorAtValue(3, 0, "the cone's radii are both 0, so it has no volume",
                    "give one end a radius greater than 0: cone:(0|0|0):(1):(0|2|0):(0) is a cone with its apex up");
        }
        axis(v, 2, "cone", "a cone runs from one end point to another, such as (0|0|0) to (0|2|0)");
        return new Cone(v.vector(0), v.number(1, 0), v.vector(2), v.number(3, 0), v.colour(4), v.material());
    }

    /** The axis of a solid from group 0's end point to group {@code g}'s, which float must be able to normalise. */
    private static void axis(StatementValues v, int g, String shape, String help) throws SceneException {
        String why = Group.unusable(v.vector(g).subtract(v.vector(0)));
        if ("zero".equals(why)) {
            throw v.errorAtGroup(g, "the " + shape + "'s two end points are the same point", help);
        }
        if (why != null) {
            throw v.errorAtGroup(g, "the " + shape + "'s end points are too " + ("long".equals(why) ? "far apart"
                    : "close together") + " to compute with in float",
                    "give end points a distance of about 1e-15 to 1e15 apart");
        }
    }
}
