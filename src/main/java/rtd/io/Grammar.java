package rtd.io;

import static rtd.io.Group.name;
import static rtd.io.Group.numbers;
import static rtd.io.Group.properties;
import static rtd.io.Group.view;
import static rtd.io.Group.word;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.io.Group.Kind;
import rtd.math.Vector3f;
import rtd.scene.AreaLight;
import rtd.scene.Light;

/**
 * The scene grammar: every statement, declared once with its keyword, its groups and how it builds its value
 * (the paper's, section 4.1; Part II's, "The scene file"). To add a statement, add one entry to
 * {@link #STATEMENTS}: the reader and the messages (the usage, the keyword list, "did you mean …?") follow
 * from it.
 */
final class Grammar {

    private static final Material DEFAULT = Material.DEFAULT;
    /** The radius from which a sphere warns of shadow acne in a shaded scene ({@link #sphere}). */
    static final float FLOOR_RADIUS = 5000;
    /** The keyword of the statement that names a value (Part III). */
    static final String LET = "let";
    private static final String VIEW_HELP = "the camera looks along it; (0|0|-1) looks into the screen";

    /** Every statement, in the order the messages list them. */
    static final List<Statement> STATEMENTS = List.of(
            Statement.setting("ambient", List.of(numbers("colour", "R|G|B")),
                    (v, out) -> out.ambient(v.colour(0))),
            Statement.setting("orthographic_camera",
                    List.of(numbers("position", "x|y|z"), view("view direction"), numbers("zoom", "zoom")),
                    (v, out) -> out.camera(camera(v, false))),
            Statement.setting("perspective_camera",
                    List.of(numbers("position", "x|y|z"), view("view direction"), numbers("field of view", "fov")),
                    (v, out) -> out.camera(camera(v, true))),
            Statement.shape("sphere",
                    List.of(numbers("centre", "x|y|z"), numbers("radius", "r"), numbers("colour", "R|G|B")),
                    (v, out) -> out.object(sphere(v, out))),
            Statement.shape("plane",
                    List.of(numbers("point", "x|y|z"), numbers("normal", "nx|ny|nz"), numbers("colour", "R|G|B")),
                    (v, out) -> out.object(new Plane(v.vector(0),
                            Directions.direction(v, 1, "the plane is at right angles to it; (0|1|0) makes a floor"), v.colour(2),
                            v.material()))),
            Statement.shape("triangle",
                    List.of(numbers("first corner", "x1|y1|z1"), numbers("second corner", "x2|y2|z2"),
                            numbers("third corner", "x3|y3|z3"), numbers("colour", "R|G|B")),
                    (v, out) -> out.object(triangle(v))),
            Statement.shape("box",
                    List.of(numbers("first corner", "x1|y1|z1"), numbers("second corner", "x2|y2|z2"),
                            numbers("colour", "R|G|B")),
                    (v, out) -> out.object(box(v))),
            Statement.shape("mesh",
                    List.of(word("file", Kind.PATH, "path"), numbers("shift", "x|y|z"), numbers("scale", "s"),
                            numbers("colour", "R|G|B")),
                    (v, out) -> {
                        Vector3f shift = v.vector(1);
                        float scale = v.positive(2);
                        Color colour = v.colour(3);
                        out.objects(ObjMesh.read(v, 0).triangles(shift, scale, colour, v.material()));
                    }),
            Statement.setting("light", List.of(numbers("position", "x|y|z"), numbers("intensity", "R|G|B")),
                    (v, out) -> out.light(new Light(v.vector(0), Rgb.of(v.colour(1))))),
            Statement.setting("material",
                    List.of(name("name", "name"), properties("properties",
                            "ambient", "diffuse", "specular", "shininess", "reflective", "transparency", "ior")),
                    (v, out) -> out.material(v.name(0), material(v))),
            Statement.shape("cylinder",
                    List.of(numbers("first end", "x1|y1|z1"), numbers("second end", "x2|y2|z2"), numbers("radius", "r"),
                            numbers("colour", "R|G|B")),
                    (v, out) -> out.object(cylinder(v))),
            Statement.shape("cone",
                    List.of(numbers("first end", "x1|y1|z1"), numbers("first radius", "r1"),
                            numbers("second end", "x2|y2|z2"), numbers("second radius", "r2"), numbers("colour", "R|G|B")),
                    (v, out) -> out.object(cone(v))),
            Statement.setting("area_light",
                    List.of(numbers("corner", "x|y|z"), numbers("first edge", "ux|uy|uz"), numbers("second edge", "vx|vy|vz"),
                            numbers("samples", "n|m"), numbers("intensity", "R|G|B")),
                    (v, out) -> {
                        AreaLight area = new AreaLight(v.vector(0), v.vector(1), v.vector(2),
                                samples(v, 3, 0, "number of samples along the first edge"),
                                samples(v, 3, 1, "number of samples along the second edge"),
                                Rgb.of(v.colour(4)));
                        area.samples().forEach(out::light);
                    }),
            new Statement("pattern", List.of(name("name", "name"), name("kind", "stripes|gradient|rings|checker"),
                    numbers("first colour", "R|G|B"), numbers("second colour", "R|G|B")),
                    List.of(name("transform", "transform")), false, Names::pattern),
            new Statement("transform", List.of(name("name", "name"), word("step", Kind.OPERATION, "scale s")),
                    List.of(word("step", Kind.OPERATION, "step")), true, Names::transform),
            Statement.setting(LET, List.of(name("name", "name"), numbers("value", "expression")),
                    (v, out) -> Names.let(v)));

    /** A {@code material}'s finish: each property given, or the default's; all at least 0, ior at least 1. */
    private static Material material(StatementValues v) throws StatementError {
        return new Material(v.property(1, "ambient", DEFAULT.ambient(), 0), v.property(1, "diffuse", DEFAULT.diffuse(), 0),
                v.property(1, "specular", DEFAULT.specular(), 0), v.property(1, "shininess", DEFAULT.shininess(), 0),
                v.property(1, "reflective", DEFAULT.reflective(), 0),
                v.property(1, "transparency", DEFAULT.transparency(), 0), v.property(1, "ior", DEFAULT.ior(), 1));
    }

    /** The keywords as bytes, beside {@link #STATEMENTS}, to find a line's statement without a String. */
    private static final byte[][] KEYWORDS = STATEMENTS.stream()
            .map(s -> s.keyword().getBytes(StandardCharsets.US_ASCII)).toArray(byte[][]::new);
    private static final Statement[] ALL = STATEMENTS.toArray(Statement[]::new);

    private Grammar() {
    }

    static Statement find(byte[] bytes, int start, int end) {
        for (int k = 0; k < ALL.length; k++) { // no Iterator for each line of a large file
            if (Arrays.equals(KEYWORDS[k], 0, KEYWORDS[k].length, bytes, start, end)) {
                return ALL[k];
            }
        }
        return null;
    }

    /** All keywords, for messages: "'ambient', 'orthographic_camera', … or 'material'". */
    static String keywordList() {
        return Hints.quoted(STATEMENTS.stream().map(Statement::keyword).toList(), "or");
    }

    /** A camera, orthographic or perspective, looking along its direction or at its point. */
    private static ICamera camera(StatementValues v, boolean perspective) throws StatementError {
        Vector3f pos = v.vector(0);
        boolean atPoint = v.isTarget(1);
        Vector3f view = atPoint ? Directions.target(v, 1, pos) : Directions.direction(v, 1, VIEW_HELP);
        if (!perspective) {
            float zoom = v.positive(2);
            return atPoint ? OrthographicCamera.lookingAt(pos, view, zoom) : new OrthographicCamera(pos, view, zoom);
        }
        float fov = v.between(2, 0, 180, "degrees", "it is the angle the picture's width spans, such as 60");
        return atPoint ? PerspectiveCamera.lookingAt(pos, view, fov) : new PerspectiveCamera(pos, view, fov);
    }

    /**
     * A sphere; one of radius {@value #FLOOR_RADIUS} or more warns in a shaded scene: on a surface that
     * large float rounds hit points by more than a shadow ray's lift, so it shows shadow acne (a radius of
     * 1000, as <i>Ray Tracing in One Weekend</i> uses, draws clean).
     */
    private static Sphere sphere(StatementValues v, SceneContents out) throws StatementError {
        Sphere sphere = new Sphere(v.vector(0), v.positive(1), v.colour(2), v.material());
        if (sphere.radius() >= FLOOR_RADIUS) {
            out.warningIfLit(v.errorAtValue(1, 0, "a sphere of radius " + v.written(1, 0)
                    + " may show shadow acne, dark speckles where it is lit: float is too coarse on a surface that large",
                    "for a floor or a wall, use a plane: plane:(0|0|0):(0|1|0):(200|200|200) is a floor at "
                    + "y = 0").place);
        }
        return sphere;
    }

    /** A triangle whose corners do not lie on one line (else it has no area and is never hit). */
    private static Triangle triangle(StatementValues v) throws StatementError {
        Vector3f p1 = v.vector(0);
        Vector3f p2 = v.vector(1);
        Vector3f p3 = v.vector(2);
        Color colour = v.colour(3);
        Vector3f n = p2.subtract(p1).cross(p3.subtract(p1)); // as the triangle computes it
        if (n.x() == 0 && n.y() == 0 && n.z() == 0) {
            throw v.errorAtGroup(0, "the corners of the triangle lie on one line, so it has no area",
                    "three corners that do not lie on one line make a triangle, such as (0|0|0), (1|0|0) and (0|1|0)");
        }
        if (!n.isFinite()) {
            throw v.errorAtGroup(0, "the triangle is too large to compute with in float",
                    "its sides must be shorter than about 1e19");
        }
        return new Triangle(p1, p2, p3, colour, v.material());
    }

    /** A box whose corners differ in every coordinate (else it is flat). */
    private static Box box(StatementValues v) throws StatementError {
        Vector3f a = v.vector(0);
        Vector3f b = v.vector(1);
        Color colour = v.colour(2);
        for (int k = 0; k < 3; k++) {
            if (v.number(0, k) == v.number(1, k)) {
                throw v.errorAtValue(1, k, "the box is flat: both corners have " + "xyz".charAt(k) + " = " + v.written(1, k),
                        "a box takes two opposite corners, which differ in x, y and z");
            }
        }
        return Box.between(a, b, colour, v.material());
    }

    /** A cylinder of radius greater than 0 between two different end points (Part III, "More shapes"). */
    private static Cylinder cylinder(StatementValues v) throws StatementError {
        Vector3f first = v.vector(0);
        Vector3f second = v.vector(1);
        float radius = v.positive(2);
        Directions.axis(v, first, second, 1, "cylinder", "a cylinder runs from one end point to another, such as (0|0|0) to (0|2|0)");
        return new Cylinder(first, second, radius, v.colour(3), v.material());
    }

    /** A cone whose radii are at least 0 and not both 0, between two different end points (Part III, "More shapes"). */
    private static Cone cone(StatementValues v) throws StatementError {
        Vector3f first = v.vector(0);
        float firstRadius = atLeastZero(v, 1);
        Vector3f second = v.vector(2);
        float secondRadius = atLeastZero(v, 3);
        if (firstRadius == 0 && secondRadius == 0) {
            throw v.errorAtValue(3, 0, "the cone's radii are both 0, so it has no volume",
                    "give one end a radius greater than 0: cone:(0|0|0):(1):(0|2|0):(0) is a cone with its apex up");
        }
        Directions.axis(v, first, second, 2, "cone", "a cone runs from one end point to another, such as (0|0|0) to (0|2|0)");
        return new Cone(first, firstRadius, second, secondRadius, v.colour(4), v.material());
    }

    /** The one number of group {@code g}, finite and at least 0: a cone's radius. */
    private static float atLeastZero(StatementValues v, int g) throws StatementError {
        float value = v.number(g, 0);
        if (value >= 0) {
            return value;
        }
        throw v.errorAtValue(g, 0, "the " + v.meaning(g) + " must be at least 0, found " + v.written(g, 0),
                "without its minus sign: " + v.written(g, 0).substring(1));
    }

    /**
     * Number {@code k} of group {@code g}: an area light's samples along one edge, 1 to {@link AreaLight#MOST_SAMPLES}.
     */
    private static int samples(StatementValues v, int g, int k, String name) throws StatementError {
        float value = v.number(g, k);
        if (value >= 1 && value <= AreaLight.MOST_SAMPLES && value == Math.rint(value)) {
            return (int) value;
        }
        throw v.errorAtValue(g, k, "the " + name + " must be a whole number from 1 to " + AreaLight.MOST_SAMPLES
                + ", found " + v.written(g, k), "more samples make a softer shadow and cost more shadow rays; 4|4 is a good start");
    }
}
