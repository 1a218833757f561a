package rtd.cli;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * The warnings, before rendering, for a scene that draws a picture without a word of why it looks wrong: a
 * camera in a plane (every ray hits it at {@code t = 0}, which wins every depth test), a camera inside a closed
 * object (every ray meets it from within), a light inside one (every point outside is in its shadow), a light so
 * dim it is black (as {@code (1|1|1)} is, The Ray Tracer Challenge's white: rtd's colours run to 255).
 */
final class SceneWarnings {

    /** The most objects looked through: a student's scene takes a millisecond, a million would take tens. */
    private static final int MOST_LOOKED_AT = 100_000;
    /** One level of 255: a light no brighter than this in every channel is all but black. */
    private static final float ONE_LEVEL = 1 / 255f;

    private SceneWarnings() {
    }

    /** The lines to print for {@code scene} (its camera as rendered), named {@code name}; the lights' if {@code lit}. */
    static List<String> of(String name, Scene scene, int width, int height, boolean lit) {
        List<String> warnings = new ArrayList<>();
        if (scene.objects().size() <= MOST_LOOKED_AT) {
            List<Ray> corners = List.of(scene.camera().generateRay(0, 0, width, height),
                    scene.camera().generateRay(width - 1, 0, width, height),
                    scene.camera().generateRay(0, height - 1, width, height),
                    scene.camera().generateRay(width - 1, height - 1, width, height));
            cameraInPlane(scene.objects(), corners).ifPresent(warnings::add);
            cameraInside(scene.objects(), corners).ifPresent(warnings::add);
            for (int i = 0; lit && i < scene.lights().size(); i++) {
                lightInside(scene.objects(), scene.lights().get(i), i + 1).ifPresent(warnings::add);
            }
        }
        for (int i = 0; lit && i < scene.lights().size(); i++) {
            Rgb c = scene.lights().get(i).intensity();
            float brightest = Math.max(c.red(), Math.max(c.green(), c.blue()));
            if (brightest > 0 && brightest <= ONE_LEVEL) {
                warnings.add("light #" + (i + 1) + " has the intensity (" + Math.round(c.red() * 255) + "|"
                        + Math.round(c.green() * 255) + "|" + Math.round(c.blue() * 255) + "), almost black: rtd's "
                        + "colours run from 0 to 255, so a full white light is (255|255|255)");
            }
        }
        warnings.replaceAll(warning -> "rtd: warning: " + name + ": " + warning);
        return warnings;
    }

    /** A plane that at least three corner rays hit where they start (the fourth may run along it). */
    private static Optional<String> cameraInPlane(List<IGeometry> objects, List<Ray> corners) {
        for (int i = 0; i < objects.size(); i++) {
            if (objects.get(i) instanceof Plane plane && corners.stream().filter(ray -> {
                Intersection hit = plane.intersect(ray);
                return hit.happened() && hit.t() == 0;
            }).count() >= 3) {
                return Optional.of("the camera stands in plane #" + (i + 1) + " (through "
                        + point(plane.point()) + ", normal " + point(plane.normal()) + "): every ray that leaves it hits "
                        + "that plane at distance 0, so the picture shows that plane alone; move the camera or the plane "
                        + "a little");
            }
        }
        return Optional.empty();
    }

    /** The first sphere or box that all four corner rays start in: being convex, it holds every ray's start. */
    private static Optional<String> cameraInside(List<IGeometry> objects, List<Ray> corners) {
        for (int i = 0; i < objects.size(); i++) {
            IGeometry object = objects.get(i);
            if (corners.stream().allMatch(ray -> inside(object, ray.origin()))) {
                return Optional.of("the camera is inside " + describe(object, i) + ": every ray starts "
                        + "inside it, so the picture shows its inside, all in one colour; move the camera out of it");
            }
        }
        return Optional.empty();
    }

    private static Optional<String> lightInside(List<IGeometry> objects, Light light, int number) {
        for (int i = 0; i < objects.size(); i++) {
            if (inside(objects.get(i), light.position())) {
                return Optional.of("light #" + number + " at " + point(light.position()) + " is inside "
                        + describe(objects.get(i), i) + ": every point outside it is in its shadow, so the light lights "
                        + "nothing outside it; move the light out of it");
            }
        }
        return Optional.empty();
    }

    /** Whether {@code p} lies strictly inside {@code object}, a sphere or a box (the closed objects). */
    private static boolean inside(IGeometry object, Vector3f p) {
        if (object instanceof Sphere sphere) {
            Vector3f d = p.subtract(sphere.center());
            return (double) d.x() * d.x() + (double) d.y() * d.y() + (double) d.z() * d.z()
                    < (double) sphere.radius() * sphere.radius();
        }
        return object instanceof Box box && box.min().x() < p.x() && p.x() < box.max().x() && box.min().y() < p.y()
                && p.y() < box.max().y() && box.min().z() < p.z() && p.z() < box.max().z();
    }

    private static String describe(IGeometry object, int index) {
        return object instanceof Sphere s ? "sphere #" + (index + 1) + " (centre " + point(s.center()) + ", radius "
                + number(s.radius()) + ")" : "box #" + (index + 1) + " (from " + point(((Box) object).min()) + " to "
                + point(((Box) object).max()) + ")";
    }

    /** A point as the scene file writes it: (0|0|20). */
    static String point(Vector3f p) {
        return "(" + number(p.x()) + "|" + number(p.y()) + "|" + number(p.z()) + ")";
    }

    /** A number in at most 6 significant digits, without needless zeros: 38.4, 20, 0.02. */
    static String number(double value) {
        return new BigDecimal(value).round(new MathContext(6)).stripTrailingZeros().toPlainString();
    }
}
