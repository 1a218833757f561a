package rtd.pov;

import static rtd.pov.PovNumbers.d;
import static rtd.pov.PovNumbers.num;
import static rtd.pov.PovNumbers.times;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import rtd.camera.ICamera;
import rtd.camera.ImageAxes;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.geometry.IGeometry;
import rtd.geometry.Patterned;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Transformed;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.io.ClockedScene;
import rtd.io.ClockedScene.ClockFields;
import rtd.io.Expression;
import rtd.math.Vector3f;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * The writer of each shape, light and colour of {@link PovScene}, and of an animated scene's numbers that use the clock
 * as POV-Ray expressions of its own {@code clock} (Part III, "Frames on the command line"), so that one file draws
 * every frame: each such number as its expression ({@link PovExpression}), each other as the number rtd holds, and
 * what rtd works out from them worked out alike in POV-Ray (a colour rounded ½ up to whole 255ths, a plane's unit
 * normal and distance, a box's smaller and larger corners, the camera's axes and half-pixel shift). It writes the
 * cameras, {@code ambient}, point lights and every shape but a mesh's; {@link #whyNot} tells what else keeps an
 * animation to be written frame by frame.
 */
public final class PovClock {

    /** The groups whose numbers it writes with the clock, for each kind of thing the scene file makes. */
    private static final Map<String, Set<String>> WRITTEN = Map.ofEntries( // ofEntries: room for more than ten
            Map.entry("sphere", Set.of("centre", "radius", "colour")),
            Map.entry("plane", Set.of("point", "normal", "colour")),
            Map.entry("triangle", Set.of("first corner", "second corner", "third corner", "colour")),
            Map.entry("box", Set.of("first corner", "second corner", "colour")),
            Map.entry("cylinder", Set.of("first end", "second end", "radius", "colour")),
            Map.entry("cone", Set.of("first end", "first radius", "second end", "second radius", "colour")),
            Map.entry("light", Set.of("position", "intensity")),
            Map.entry("camera", Set.of("position", "view direction", "field of view", "zoom")),
            Map.entry("ambient", Set.of("colour")));

    /** A still: no number uses the clock. */
    static final PovClock STILL = new PovClock(null);

    private final ClockedScene clocked;

    PovClock(ClockedScene clocked) {
        this.clocked = clocked;
    }

    /** The {@code #declare} of each {@code let} name that a number using the clock uses, to stand before the camera. */
    String declarations() {
        Stream<ClockFields> parts = Stream.concat(Stream.of(clocked.ambient(), clocked.camera()),
                Stream.concat(clocked.scene().lights().stream(), clocked.scene().objects().stream()).map(clocked::of));
        return PovExpression.declarations(parts.flatMap(fields -> fields.expressions().stream()).toList());
    }

    /**
     * Why {@code clocked} cannot be written as one POV-Ray file that follows the clock, or null if it can;
     * {@code cameras}, the camera at every frame, must have image axes that POV-Ray's {@code vcross} gives (rtd's
     * camera looking straight up or down takes x as its right axis).
     */
    public static String whyNot(ClockedScene clocked, List<ICamera> cameras) {
        List<String> reasons = new ArrayList<>(clocked.unwritten());
        Scene scene = clocked.scene();
        check(reasons, "ambient", "'ambient'", clocked.ambient());
        check(reasons, "camera", "the camera", clocked.camera());
        for (Light light : scene.lights()) {
            check(reasons, "light", "a light", clocked.of(light));
        }
        for (IGeometry object : scene.objects()) {
            ClockFields fields = clocked.of(object);
            IGeometry shape = object instanceof Transformed transformed ? transformed.shape() : object;
            if (shape instanceof Patterned && !fields.isEmpty()) {
                reasons.add("a " + shape.kind() + " with a pattern, which follows its numbers");
            }
            check(reasons, shape.kind(), "a " + shape.kind(), fields);
        }
        if (!clocked.camera().isEmpty()
                && cameras.stream().anyMatch(c -> ImageAxes.looksStraightUpOrDown(direction(c)))) {
            reasons.add("the camera, which looks straight up or down at a frame");
        }
        return reasons.isEmpty() ? null : String.join("; ", reasons);
    }

    private static void check(List<String> reasons, String kind, String what, ClockFields fields) {
        Set<String> written = WRITTEN.getOrDefault(kind, Set.of());
        fields.groups().stream().filter(group -> !written.contains(group)).forEach(group -> reasons.add("the " + group
                + " of " + what));
    }

    private static Vector3f direction(ICamera camera) {
        return camera instanceof PerspectiveCamera p ? p.direction() : ((OrthographicCamera) camera).direction();
    }

    /** The numbers of {@code part}'s statement that use the clock; null for a still. */
    ClockFields of(Object part) {
        return clocked == null ? null : clocked.of(part);
    }

    ClockFields ambient() {
        return clocked == null ? null : clocked.ambient();
    }

    /**
     * The sum of the lights' intensities, POV-Ray's {@code ambient_light}
     * for a shaded scene; null if none uses the clock.
     */
    String lightSum(List<Light> lights) {
        if (clocked == null || lights.stream().noneMatch(light -> clocked.of(light).groups().contains("intensity"))) {
            return null; // the sum as rtd adds it, in float
        }
        return "rgb <" + IntStream.range(0, 3).mapToObj(k -> lights.stream()
                .map(light -> channel(clocked.of(light), "intensity", k, part(light.intensity(), k)))
                .collect(Collectors.joining(" + "))).collect(Collectors.joining(", ")) + ">";
    }

    /** The camera, if a number of its statement uses the clock; else null. */
    String camera(ICamera camera, int w, int h) {
        ClockFields f = clocked == null ? ClockFields.NONE : clocked.camera();
        return f.isEmpty() ? null : PovCamera.withClock(f, camera, w, h);
    }

    /** A point light; {@code f} its numbers that use the clock, or null for a still (its vectors in double). */
    static String light(Light light, ClockFields f) {
        return "light_source { " + vector(f, "position", light.position()) + ", rgb <"
                + channels(f, "intensity", light.intensity()) + "> }\n";
    }

    /** A shape's colour, as {@code rgb <…>} or, with a share let through ({@code filter > 0}), as {@code rgbt <…>}. */
    static String pigment(ClockFields f, Color colour, float filter) {
        String channels = channels(f, "colour", Rgb.of(colour));
        return filter <= 0 ? "pigment { rgb <" + channels + "> }"
                : "pigment { rgbt <" + channels + ", " + num(filter) + "> }";
    }

    /** {@code colour} as {@code rgb <…>}, its channels from {@code group} where they use the clock. */
    static String rgb(ClockFields f, String group, Color colour) {
        return "rgb <" + channels(f, group, Rgb.of(colour)) + ">";
    }

    private static String channels(ClockFields f, String group, Rgb c) {
        return IntStream.range(0, 3).mapToObj(k -> channel(f, group, k, part(c, k))).collect(Collectors.joining(", "));
    }

    private static float part(Rgb c, int k) {
        return k == 0 ? c.red() : k == 1 ? c.green() : c.blue();
    }

    /** Channel {@code k} of a colour group: rtd rounds an expression ½ up to a whole number, then takes 255ths. */
    private static String channel(ClockFields f, String group, int k, float fraction) {
        Expression e = f == null ? null : f.of(group, k);
        return e == null ? num(fraction) : "floor(" + PovExpression.of(e) + " + 0.5) / 255";
    }

    /**
     * A shape up to its pigment, {@code sphere { <…>, r}; {@code f} its statement's numbers that use the clock, or null
     * for a still. One method for all shapes, so a new shape cannot be half added.
     */
    static String shape(IGeometry shape, ClockFields f) {
        if (shape instanceof Sphere s) {
            return "sphere { " + vector(f, "centre", s.center()) + ", " + number(f, "radius", 0, s.radius());
        }
        if (shape instanceof Plane p) {
            return f == null ? plane(p) : "plane { vnormalize(" + vector(f, "normal", p.normal()) + "), vdot("
                    + vector(f, "point", p.point()) + ", vnormalize(" + vector(f, "normal", p.normal()) + "))";
        }
        if (shape instanceof Triangle t && t.isSmooth()) {
            String corners = "";
            for (int k = 0; k < 3; k++) {
                corners += (k > 0 ? ", " : "") + PovNumbers.vector(t.corner(k)) + ", "
                        + PovNumbers.vector(t.cornerNormal(k));
            }
            return "smooth_triangle { " + corners;
        }
        if (shape instanceof Triangle t) {
            return "triangle { " + vector(f, "first corner", t.corner(0))
                    + ", " + vector(f, "second corner", t.corner(1))
                    + ", " + vector(f, "third corner", t.corner(2));
        }
        if (shape instanceof Box b) {
            return "box { " + (f == null ? PovNumbers.vector(b.min()) + ", " + PovNumbers.vector(b.max())
                    : corners(f, b));
        }
        if (shape instanceof Cylinder c) { // closed by its caps, as POV-Ray's is unless it is "open"
            return "cylinder { " + vector(f, "first end", c.first()) + ", " + vector(f, "second end", c.second()) + ", "
                    + number(f, "radius", 0, c.radius());
        }
        if (shape instanceof Cone c) {
            return "cone { " + vector(f, "first end", c.first()) + ", " + number(f, "first radius", 0, c.firstRadius())
                    + ", " + vector(f, "second end", c.second())
                    + ", " + number(f, "second radius", 0, c.secondRadius());
        }
        throw new IllegalArgumentException("no POV-Ray shape for a " + shape.kind());
    }

    /** A still plane: its unit normal and its distance from the origin, worked out in double. */
    private static String plane(Plane p) {
        double[] n = d(p.normal());
        double[] unit = times(n, 1 / Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
        double[] q = d(p.point());
        return "plane { " + PovNumbers.vector(unit) + ", " + num(q[0] * unit[0] + q[1] * unit[1] + q[2] * unit[2]);
    }

    /** A box's smaller corner and its larger, as rtd's box takes them from the two corners written. */
    private static String corners(ClockFields f, Box box) {
        float[] min = {box.min().x(), box.min().y(), box.min().z()};
        float[] max = {box.max().x(), box.max().y(), box.max().z()};
        String[] low = new String[3];
        String[] high = new String[3];
        for (int k = 0; k < 3; k++) {
            if (f.of("first corner", k) == null && f.of("second corner", k) == null) {
                low[k] = num(min[k]);
                high[k] = num(max[k]);
            } else {
                String a = number(f, "first corner", k, f.value("first corner", k));
                String b = number(f, "second corner", k, f.value("second corner", k));
                low[k] = "min(" + a + ", " + b + ")";
                high[k] = "max(" + a + ", " + b + ")";
            }
        }
        return "<" + String.join(", ", low) + ">, <" + String.join(", ", high) + ">";
    }

    /** Number {@code k} of {@code group}: its expression if it uses the clock, else {@code value}. */
    static String number(ClockFields f, String group, int k, float value) {
        Expression e = f == null ? null : f.of(group, k);
        return e == null ? num(value) : PovExpression.of(e);
    }

    /**
     * The three numbers of {@code group}, each its expression if it uses the clock, else {@code v}'s; for a still
     * ({@code f} null), {@code v} worked out in double, as the still export writes its vectors.
     */
    static String vector(ClockFields f, String group, Vector3f v) {
        return f == null ? PovNumbers.vector(v)
                : "<" + number(f, group, 0, v.x()) + ", " + number(f, group, 1, v.y()) + ", "
                        + number(f, group, 2, v.z()) + ">";
    }
}
