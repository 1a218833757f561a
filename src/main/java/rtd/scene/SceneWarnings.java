package rtd.scene;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.IntStream;
import rtd.geometry.BoundingBox;
import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The warnings, before rendering, for a scene that draws a picture without a word of why it looks wrong: a
 * camera in a plane (every ray hits it at {@code t = 0}, which wins every depth test), a camera alone inside a
 * closed object, a sphere or box (every ray meets it from within), a light inside one that the camera sees from
 * outside (every point outside is in its shadow), a light so dim it is black (as {@code (1|1|1)} is, The Ray
 * Tracer Challenge's white: rtd's colours run to 255). The scene keeps no places in its file, so objects and lights
 * are named by their number, as {@code --explain} numbers them.
 */
public final class SceneWarnings {

    /** The most objects looked through: any student's scene, while a million objects are not held up. */
    private static final int MOST_LOOKED_AT = 100_000;
    /** One level of 255: a light no brighter than this in every channel is all but black. */
    private static final float ONE_LEVEL = 1 / 255f;

    private SceneWarnings() {
    }

    /**
     * The warnings for {@code scene} (its camera as rendered at {@code width × height}); the lights' if {@code lit}.
     */
    public static List<String> of(Scene scene, int width, int height, boolean lit) {
        List<String> warnings = new ArrayList<>();
        List<IGeometry> objects = scene.objects();
        if (objects.size() <= MOST_LOOKED_AT) {
            List<Ray> corners = List.of(scene.camera().generateRay(0, 0, width, height),
                    scene.camera().generateRay(width - 1, 0, width, height),
                    scene.camera().generateRay(0, height - 1, width, height),
                    scene.camera().generateRay(width - 1, height - 1, width, height));
            cameraInPlane(objects, corners).ifPresent(warnings::add);
            cameraInside(objects, corners, lit && !scene.lights().isEmpty()).ifPresent(warnings::add);
            AreaLight warned = null; // an area light's samples: one warning for them all
            for (int i = 0; lit && i < scene.lights().size(); i++) {
                Light light = scene.lights().get(i);
                if (light.area() == null || light.area() != warned) {
                    Optional<String> inside = lightInside(objects, corners, light, name(light, i));
                    inside.ifPresent(warnings::add);
                    warned = inside.isPresent() ? light.area() : warned;
                }
            }
        }
        AreaLight seen = null;
        for (int i = 0; lit && i < scene.lights().size(); i++) {
            Light light = scene.lights().get(i);
            if (light.area() != null && light.area() == seen) {
                continue;
            }
            seen = light.area();
            Rgb c = seen == null ? light.intensity() : seen.intensity(); // the whole area light's, not a sample's share
            float brightest = Math.max(c.red(), Math.max(c.green(), c.blue()));
            if (brightest > 0 && brightest <= ONE_LEVEL) {
                warnings.add((seen == null ? "light #" + (i + 1) : "the area light with corner " + point(seen.corner()))
                        + " has the intensity (" + Math.round(c.red() * 255) + "|"
                        + Math.round(c.green() * 255) + "|" + Math.round(c.blue() * 255) + "), almost black: rtd's "
                        + "colours run from 0 to 255, so a full white light is (255|255|255)");
            }
        }
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
                        + point(plane.point()) + ", normal " + point(plane.normal())
                        + "): every ray that leaves it hits "
                        + "that plane at distance 0, so the picture shows that plane alone; "
                        + "move the camera or the plane "
                        + "a little");
            }
        }
        return Optional.empty();
    }

    /**
     * A sphere or box that every ray starts in (being convex, it holds them all if it holds the four corners'), with
     * nothing else in reach of its box: a room with objects inside it is no mistake. Its inside shows in one flat
     * colour unless the scene is {@code shaded}.
     */
    private static Optional<String> cameraInside(List<IGeometry> objects, List<Ray> corners, boolean shaded) {
        int room = enclosing(objects, corners);
        if (room < 0) {
            return Optional.empty();
        }
        BoundingBox box = objects.get(room).bounds();
        if (IntStream.range(0, objects.size()).anyMatch(i -> i != room && overlap(objects.get(i).bounds(), box))) {
            return Optional.empty();
        }
        return Optional.of("the camera is inside " + describe(objects.get(room), room)
                + ": every ray starts inside it, "
                + "so the picture shows its inside" + (shaded ? "" : ", all in one colour")
                + "; move the camera out of it");
    }

    /** A sphere or box that holds the light but not the camera, which sees its outside only. */
    private static Optional<String> lightInside(List<IGeometry> objects, List<Ray> corners, Light light, String name) {
        for (int i = 0; i < objects.size(); i++) {
            if (inside(objects.get(i), light.position()) && !holdsAll(objects.get(i), corners)) {
                return Optional.of(name + " at " + point(light.position()) + " is inside "
                        + describe(objects.get(i), i)
                        + ": every point outside it is in its shadow, so the light lights "
                        + "nothing outside it; move the light out of it");
            }
        }
        return Optional.empty();
    }

    /** "light #3", as {@code --explain} numbers the point lights; "a sample of the area light with corner (x|y|z)". */
    private static String name(Light light, int index) {
        return light.area() == null ? "light #" + (index + 1)
                : "a sample of the area light with corner " + point(light.area().corner());
    }

    /** The first object that every corner ray starts in, or −1. */
    private static int enclosing(List<IGeometry> objects, List<Ray> corners) {
        for (int i = 0; i < objects.size(); i++) { // loops, not streams: these run on every first run
            if (holdsAll(objects.get(i), corners)) {
                return i;
            }
        }
        return -1;
    }

    /** Whether {@code a} (unbounded: a plane, which may cross anything) and {@code b} share a point. */
    private static boolean overlap(BoundingBox a, BoundingBox b) {
        return !a.isBounded() || a.min().x() <= b.max().x() && b.min().x() <= a.max().x() && a.min().y() <= b.max().y()
                && b.min().y() <= a.max().y() && a.min().z() <= b.max().z() && b.min().z() <= a.max().z();
    }

    private static boolean holdsAll(IGeometry object, List<Ray> corners) {
        for (Ray ray : corners) {
            if (!inside(object, ray.origin())) {
                return false;
            }
        }
        return true;
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
    public static String point(Vector3f p) {
        return "(" + number(p.x()) + "|" + number(p.y()) + "|" + number(p.z()) + ")";
    }

    /** A number in at most 6 significant digits, without needless zeros: 38.4, 20, 0.02. */
    public static String number(double value) {
        return new BigDecimal(value).round(new MathContext(6)).stripTrailingZeros().toPlainString();
    }
}
