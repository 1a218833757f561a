package rtd.pov;

import static rtd.pov.PovNumbers.d;
import static rtd.pov.PovNumbers.num;
import static rtd.pov.PovNumbers.plus;
import static rtd.pov.PovNumbers.rgb;
import static rtd.pov.PovNumbers.times;
import static rtd.pov.PovNumbers.vector;

import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Pattern;
import rtd.geometry.Patterned;
import rtd.geometry.Transformed;
import rtd.image.Rgb;
import rtd.io.ClockedScene;
import rtd.io.ClockedScene.ClockFields;
import rtd.scene.AreaLight;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * A scene written as a POV-Ray 3.7 scene that draws the same picture ({@code --export-pov}): a second, independent ray
 * tracer to check rtd against. What makes the two agree:
 * <ul>
 * <li>the camera as explicit vectors ({@link PovCamera}): POV-Ray's {@code right} along rtd's u, its {@code up} against
 *     rtd's v (which points down), shifted from POV-Ray's pixel centres to rtd's corners (Listing 4.1);</li>
 * <li>flat scenes: {@code finish { ambient 1 diffuse 0 }} and {@code ambient_light 1}, no lights, so each object shows
 *     its colour exactly;</li>
 * <li>shaded scenes: {@code phong} is the specular term, {@code phong_size} the shininess, the ambient light the sum of
 *     the lights' intensities, {@code max_trace_level 6} counts the camera's ray as rtd's 5 bounces do not;
 *     transparent objects use {@code rgbt}, their shadow left to an opaque, invisible twin, as every object of rtd's
 *     casts a full shadow;</li>
 * <li>gamma 1: values are linear, as rtd's; an animation's numbers that use the clock in POV-Ray's {@code clock}
 *     ({@link PovClock}).</li>
 * </ul>
 */
public final class PovScene {

    private PovScene() {
    }

    /** The POV-Ray command that renders {@code povFile} at {@code w × h} into {@code png}, as rtd would. */
    public static String command(String povFile, String png, int w, int h) {
        return "povray " + shellWord("+I" + povName(povFile)) + " " + shellWord("+O" + povName(png)) + " +W" + w + " +H"
                + h + " +FN -A -D File_Gamma=1.0";
    }

    /**
     * A file name as POV-Ray's options take it: in double quotes if it has anything but letters, digits and
     * {@code _./+:,@%-} (where POV-Ray may end an option's name); {@code --export-pov} refuses a name with a quote.
     */
    private static String povName(String name) {
        return name.matches("[A-Za-z0-9_./+:,@%-]+") ? name : '"' + name + '"';
    }

    /** {@code word} as a shell reads it back: as it is if it is plain, else in single quotes (a name with spaces). */
    public static String shellWord(String word) {
        return word.matches("[A-Za-z0-9_./+=:,@%-]+") ? word : "'" + word.replace("'", "'\\''") + "'";
    }

    /**
     * The POV-Ray text of {@code scene} as rtd draws it at
     * {@code w × h}; {@code povFile} names the file, for the comment.
     */
    public static String of(Scene scene, int w, int h, String povFile) {
        return "// A POV-Ray 3.7 twin of an rtd scene, written by rtd --export-pov. Render it at rtd's size with\n//   "
                + command(povFile, povFile.replaceAll("(?i)\\.pov$", "") + "-pov.png", w, h) + "\n"
                + notes(scene, "// and compare")
                + "#version 3.7;\n\n" + body(scene, w, h, PovClock.STILL);
    }

    /**
     * As above, each number that uses the clock written with POV-Ray's {@code clock}, so that the one file draws every
     * frame; only for a scene that {@link PovClock#whyNot} passes. The command that renders it is the caller's.
     */
    public static String of(ClockedScene clocked, int w, int h) {
        PovClock clock = new PovClock(clocked);
        return notes(clocked.scene(), "// Compare") + "#version 3.7;\n\n" + clock.declarations()
                + body(clocked.scene(), w, h, clock);
    }

    /** The scene alone, without the comments and the {@code #version} of a file: one frame among others. */
    public static String frame(Scene scene, int w, int h) {
        return body(scene, w, h, PovClock.STILL);
    }

    /** What to expect when comparing the pictures, after {@code opening}. */
    private static String notes(Scene scene, String opening) {
        String notes = opening + (!scene.lights().isEmpty()
                ? " decoded pixels: shaded scenes agree but for shadow and silhouette edges and a level here\n"
                        + "// and there (POV-Ray aims shadow rays from P, rtd from just above it); "
                        + "glass that also mirrors uses\n"
                        + "// POV-Ray's own Fresnel reflection, close to rtd's Schlick mix but not the same.\n"
                : " decoded pixels: flat scenes agree but for the odd pixel on an edge.\n");
        if (scene.lights().stream().anyMatch(light -> light.area() != null)) {
            notes += "// Area lights: their lights fall on rtd's samples and cast the same soft shadows; "
                    + "POV-Ray lights with\n"
                    + "// each area light's centre where rtd sums its samples, so highlights differ a little.\n";
        }
        return notes;
    }

    /** The settings, camera, lights and objects, the numbers that use the clock written by {@code clock}. */
    private static String body(Scene scene, int w, int h, PovClock clock) {
        boolean shaded = !scene.lights().isEmpty();
        StringBuilder pov = new StringBuilder();
        String lightSum = clock.lightSum(scene.lights());
        if (lightSum == null) { // the sum as rtd adds it, in float
            lightSum = rgb(scene.lights().stream().map(Light::intensity).reduce(Rgb.BLACK, Rgb::plus));
        }
        pov.append("global_settings { assumed_gamma 1.0 ambient_light ").append(shaded ? lightSum : "rgb <1, 1, 1>")
                .append(shaded ? " max_trace_level " + 6 + " adc_bailout 0" : "").append(" }\n");
        pov.append("background { ").append(PovClock.rgb(clock.ambient(), "colour", scene.ambient())).append(" }\n\n");
        String moving = clock.camera(scene.camera(), w, h);
        pov.append(moving != null ? moving : PovCamera.of(scene.camera(), w, h)).append('\n');
        AreaLight written = null;
        for (Light light : scene.lights()) {
            if (light.area() == null) {
                pov.append(PovClock.light(light, clock.of(light)));
            } else if (light.area() != written) { // its samples follow one another: the first writes it
                written = light.area();
                pov.append(areaLight(written));
            }
        }
        for (IGeometry object : scene.objects()) {
            pov.append(object(object, shaded, clock.of(object)));
        }
        return pov.toString();
    }

    /**
     * An area light as POV-Ray's {@code area_light}, its lights on rtd's samples: POV-Ray centres the rectangle on its
     * location and spreads its n lights from one end of an axis to the other, rtd puts them at {@code (i + ½)/n} of the
     * edge, so the location is {@code C + u/2 + v/2} and the axes {@code u·(n − 1)/n} and {@code v·(m − 1)/m}; without
     * {@code adaptive} or {@code jitter}, every light is tested where it is.
     */
    private static String areaLight(AreaLight area) {
        double[] u = d(area.u());
        double[] v = d(area.v());
        double[] centre = plus(plus(d(area.corner()), times(u, 0.5)), times(v, 0.5));
        double[] axis1 = area.n() == 1 ? u : times(u, (area.n() - 1.0) / area.n());
        double[] axis2 = area.m() == 1 ? v : times(v, (area.m() - 1.0) / area.m());
        return "light_source { " + vector(centre) + ", " + rgb(area.intensity()) + " area_light " + vector(axis1) + ", "
                + vector(axis2) + ", " + area.n() + ", " + area.m() + " }\n";
    }

    /** The object; {@code f} its numbers that use the clock, or null or none for one that does not. */
    private static String object(IGeometry object, boolean shaded, ClockFields f) {
        IGeometry shape = object;
        String end = " }";
        if (shape instanceof Transformed transformed) { // the matrix after the pigment moves the pattern too
            end = " " + PovPaint.matrix(transformed.matrix()) + " }";
            shape = transformed.shape();
        }
        Pattern pattern = shape instanceof Patterned patterned ? patterned.pattern() : null;
        shape = shape instanceof Patterned patterned ? patterned.shape() : shape;
        f = f == null || f.isEmpty() ? null : f;
        String start = PovClock.shape(shape, f); // "sphere { <x, y, z>, r"
        if (!shaded) {
            return start + " " + pigment(object, shape, pattern, 0, f) + " finish { ambient 1 diffuse 0 }" + end + "\n";
        }
        Material m = object.material();
        if (m.transparency() <= 0) {
            return start + " " + pigment(object, shape, pattern, 0, f) + " " + finish(m, 1) + end + "\n";
        }
        float t = Math.min(m.transparency(), 0.999f); // POV-Ray's rgbt of 1 would leave no share to scale by
        return start + " " + pigment(object, shape, pattern, t, f) + " " + finish(m, 1 - t) + " interior { ior "
                + num(m.ior()) + " } no_shadow" + end + "\n"
                + start + " pigment { rgb 0 } no_image no_reflection" + end + " // its shadow\n";
    }

    /** A flat colour's pigment, or a pattern's; {@code filter} is rgbt's share let through (0: plain rgb). */
    private static String pigment(IGeometry object, IGeometry shape, Pattern pattern, float filter, ClockFields f) {
        return pattern != null ? PovPaint.pigment(shape, pattern, filter) : PovClock.pigment(f, object.color(), filter);
    }

    /** rtd's finish (The Ray Tracer Challenge's), ambient and diffuse scaled by {@code 1/share} where rgbt filters. */
    private static String finish(Material m, float share) {
        return "finish { ambient " + num(m.ambient() / share) + " diffuse " + num(m.diffuse() / share) + " phong "
                + num(m.specular()) + " phong_size " + num(m.shininess())
                + reflection(m) + " }";
    }

    /**
     * The mirror's share. Where glass also mirrors, rtd mixes the two by Schlick's approximation of Fresnel; POV-Ray's
     * twin is its own Fresnel reflection with {@code conserve_energy}: not the same formula, but far nearer than a
     * plain reflection added to the light let through.
     */
    private static String reflection(Material m) {
        if (m.reflective() <= 0) {
            return "";
        }
        return m.transparency() > 0
                ? " reflection { 0, " + num(m.reflective()) + " fresnel on } conserve_energy"
                : " reflection { " + num(m.reflective()) + " }";
    }
}
