package rtd.cli;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.List;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.BoundingBox;
import rtd.geometry.IGeometry;
import rtd.image.Picture;
import rtd.math.Vector3f;
import rtd.scene.Scene;

/**
 * The warning for a picture in which no ray hit anything: a plain background, which a user
 * would otherwise take for a bug. It names the likely cause: no objects, objects behind the
 * camera, or (for the orthographic camera) the visible region in world units and that no object
 * is in it, or that the objects in it fall between the rays.
 */
final class NothingInView {

    private NothingInView() {
    }

    /**
     * Whether some pixel of {@code picture} is not the background: then some ray surely hit. A
     * picture of background alone is not proof of the opposite when an object has the
     * background's colour.
     */
    static boolean showsSomething(Picture picture, int background) {
        for (int pixel : picture.rgb()) {
            if (pixel != background) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether some object may be drawn in the background colour, so that its hits do not show: in
     * a shaded scene any may (under a black light, or in shadow); in a flat one, one painted in it.
     */
    static boolean someObjectLooksLikeBackground(Scene scene) {
        if (!scene.lights().isEmpty()) {
            return true;
        }
        int background = scene.ambient().getRGB();
        return scene.objects().stream().anyMatch(object -> object.color().getRGB() == background);
    }

    /** The one-line warning for {@code scene} (its camera as rendered), named {@code name}, at {@code width × height}. */
    static String warning(String name, Scene scene, int width, int height) {
        return "rtd: warning: " + name + ": no ray hit anything, so the picture is only background: "
                + cause(scene, width, height);
    }

    private static String cause(Scene scene, int width, int height) {
        List<IGeometry> objects = scene.objects();
        ICamera camera = scene.camera();
        if (objects.isEmpty()) {
            return "the scene has no objects";
        }
        Vector3f forward = forward(camera);
        long behind = forward == null ? 0 : objects.stream().filter(o -> isBehind(o.bounds(), camera.position(), forward)).count();
        if (behind == objects.size()) {
            return (objects.size() == 1 ? "the one object is" : "all " + objects.size() + " objects are")
                    + " behind the camera, which looks along " + point(forward) + " from "
                    + point(camera.position());
        }
        String someBehind = behind == 0 ? "" : " (" + behind + " of the " + objects.size() + " objects " + (behind == 1 ? "is" : "are") + " behind it)";
        if (camera instanceof OrthographicCamera orthographic) {
            return orthographicCause(orthographic, objects, width, height) + someBehind;
        }
        if (camera instanceof PerspectiveCamera perspective) {
            return "no object is within the camera's " + number(perspective.fieldOfView()) + "° field of view from "
                    + point(camera.position()) + " along " + point(perspective.direction()) + someBehind;
        }
        return "no object is in the camera's view" + someBehind;
    }

    private static String orthographicCause(OrthographicCamera camera, List<IGeometry> objects, int width, int height) {
        double zoom = camera.zoom();
        Region region = Region.of(camera, width, height);
        String seen = "the camera sees " + number(width / zoom) + " × " + number(height / zoom) + " world units around "
                + point(camera.position()) + " (width/zoom × height/zoom)";
        boolean someoneInRegion = objects.stream().map(IGeometry::bounds)
                .anyMatch(box -> !box.isBounded() || region.overlaps(box));
        if (someoneInRegion) {
            return seen + ", and the objects there fall between its rays, which are " + number(1 / zoom)
                    + " world units apart (1/zoom); raise the zoom";
        }
        return seen + ", and no object is in that region; move the camera, or lower its zoom to see more";
    }

    /** The part of the image plane that the rays leave from, in front of an orthographic camera. */
    private record Region(OrthographicCamera camera, double left, double right, double top, double bottom) {

        static Region of(OrthographicCamera camera, int width, int height) {
            double zoom = camera.zoom();
            // Listing 4.1: offsets from -(w/2) to w - 1 - w/2 pixels, one pixel more for the rays' spacing
            return new Region(camera, -(width / 2) / zoom, (width - width / 2) / zoom,
                    -(height / 2) / zoom, (height - height / 2) / zoom);
        }

        /** Whether {@code box} lies in front of the camera and reaches into the region as seen along the view. */
        boolean overlaps(BoundingBox box) {
            double[] u = range(box, camera.widthVector());
            double[] v = range(box, camera.heightVector());
            return u[1] >= left && u[0] <= right && v[1] >= top && v[0] <= bottom
                    && !isBehind(box, camera.position(), camera.direction());
        }

        private double[] range(BoundingBox box, Vector3f axis) {
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            for (Vector3f corner : corners(box)) {
                double along = corner.subtract(camera.position()).dot(axis);
                low = Math.min(low, along);
                high = Math.max(high, along);
            }
            return new double[] {low, high};
        }
    }

    /** Whether every corner of {@code box} lies behind the plane through {@code position} facing {@code forward}. */
    private static boolean isBehind(BoundingBox box, Vector3f position, Vector3f forward) {
        if (!box.isBounded()) {
            return false;
        }
        for (Vector3f corner : corners(box)) {
            if (corner.subtract(position).dot(forward) >= 0) {
                return false;
            }
        }
        return true;
    }

    private static Vector3f[] corners(BoundingBox box) {
        Vector3f a = box.min();
        Vector3f b = box.max();
        return new Vector3f[] {a, new Vector3f(b.x(), a.y(), a.z()), new Vector3f(a.x(), b.y(), a.z()),
            new Vector3f(a.x(), a.y(), b.z()), new Vector3f(b.x(), b.y(), a.z()), new Vector3f(b.x(), a.y(), b.z()),
            new Vector3f(a.x(), b.y(), b.z()), b};
    }

    /** The view direction as the scene file gave it, or null for a camera that does not tell. */
    private static Vector3f forward(ICamera camera) {
        if (camera instanceof OrthographicCamera orthographic) {
            return orthographic.direction();
        }
        if (camera instanceof PerspectiveCamera perspective) {
            return perspective.direction();
        }
        return null;
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
