package rtd.cli;

import static rtd.scene.SceneWarnings.number;
import static rtd.scene.SceneWarnings.point;

import java.util.DoubleSummaryStatistics;
import java.util.List;
import java.util.function.Supplier;
import java.util.stream.IntStream;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.BoundingBox;
import rtd.geometry.IGeometry;
import rtd.geometry.Plane;
import rtd.image.Picture;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.Shader;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * The warning for a picture in which no ray hit anything, which a user would otherwise take for a bug, naming the
 * likely cause: no objects, objects behind the camera or out of its view, or objects that fall between the rays.
 */
final class NothingInView {

    /**
     * Whether some ray of {@code picture} hit an object: a pixel that is not background says so; if an object may
     * look like background (any, in a lit scene), the rays are traced again with a shader that marks hits.
     */
    static boolean hitSomething(Scene scene, Supplier<Tracer> tracers, Picture picture, int threads) {
        int background = scene.ambient().getRGB();
        if (!allEqual(picture.rgb(), background)) {
            return true;
        }
        if (scene.lights().isEmpty()
                && scene.objects().stream().noneMatch(o -> o.isPatterned() || o.color().getRGB() == background)) {
            return false;
        }
        Shader hitMarks = (rays, hits, i) -> hits.index(i) < 0 ? Rgb.BLACK : new Rgb(1, 1, 1);
        Picture marks = ParallelRenderer.render(scene.camera(), tracers, tracer -> hitMarks, picture.width(),
                picture.height(), threads, new RenderProgress()).image();
        return !allEqual(marks.rgb(), 0);
    }

    /** Whether every pixel is {@code rgb}: a plain loop, as a stream would cost a first run more than the test. */
    private static boolean allEqual(int[] pixels, int rgb) {
        for (int pixel : pixels) {
            if (pixel != rgb) {
                return false;
            }
        }
        return true;
    }

    /** The one-line warning for {@code scene} (its camera as rendered), named {@code name}. */
    static String warning(String name, Scene scene, RenderOptions options) {
        return "rtd: warning: " + name + ": no ray hit anything, so the picture is only background: "
                + cause(scene, options);
    }

    private static String cause(Scene scene, RenderOptions options) {
        ICamera camera = scene.camera(); // a scene file's: orthographic or perspective
        OrthographicCamera orthographic = camera instanceof OrthographicCamera o ? o : null;
        Vector3f forward = orthographic != null ? orthographic.direction() : ((PerspectiveCamera) camera).direction();
        List<IGeometry> objects = scene.objects().stream().filter(o -> !(o instanceof Plane)).toList();
        if (scene.objects().isEmpty()) {
            return "the scene has no objects";
        } else if (objects.isEmpty()) {
            return planesMissed(scene.objects().size(), camera, forward);
        }
        // no ray met a plane
        long behind = objects.stream().filter(o -> isBehind(o.bounds(), camera.position(), forward)).count();
        if (behind == objects.size()) {
            return (objects.size() == 1 ? "the one object is" : "all " + objects.size() + " objects are")
                    + " behind the camera, which looks along " + point(forward) + " from " + point(camera.position());
        }
        String someBehind = behind == 0 ? "" : " (" + behind + " of the " + objects.size() + " objects "
                + (behind == 1 ? "is" : "are") + " behind it)";
        return (orthographic != null ? orthographicCause(orthographic, objects, options) : "no object is within the "
                + "camera's " + number(((PerspectiveCamera) camera).fieldOfView()) + "° field of view from "
                + point(camera.position()) + " along " + point(forward)) + someBehind;
    }

    /** Why no ray meets the planes, the only objects: every ray not parallel to one that runs towards it meets it. */
    private static String planesMissed(int planes, ICamera camera, Vector3f forward) {
        String them = planes == 1 ? "the plane" : "all " + planes + " planes";
        String it = planes == 1 ? "it" : "them";
        String from = " from " + point(camera.position()) + " along " + point(forward);
        if (camera instanceof PerspectiveCamera) {
            return them + (planes == 1 ? " lies" : " lie") + " outside the camera's field of view" + from
                    + "; turn the camera towards " + it;
        }
        return "the camera's rays" + from + " run parallel to " + them + " or away from " + it + "; tilt the camera "
                + "towards " + it + ", as (0|-1|-1) looks down onto a floor";
    }

    private static String orthographicCause(OrthographicCamera camera, List<IGeometry> objects, RenderOptions options) {
        int width = options.width();
        int height = options.height();
        double zoom = camera.zoom();
        String seen = "the camera sees " + number(width / zoom) + " × " + number(height / zoom) + " world units around "
                + point(camera.position()) + " (width/zoom × height/zoom)";
        if (objects.stream().anyMatch(o -> inRegion(o.bounds(), camera, width, height))) {
            return seen + ", and the objects there fall between its rays, which are " + number(1 / zoom)
                    + " world units apart (1/zoom); raise the zoom";
        }
        return seen + ", and no object is in that region; move the camera, or lower its zoom to see more"
                + scaleHint(camera, objects, options);
    }

    /** For a size of the default's shape, where the default size shows an object: the {@code --scale} that does. */
    private static String scaleHint(OrthographicCamera camera, List<IGeometry> objects, RenderOptions options) {
        int w = RtdCommand.DEFAULT_WIDTH;
        int h = RtdCommand.DEFAULT_HEIGHT;
        Scale scale = new Scale(Double.parseDouble(number(options.width() / (double) w)));
        if (!options.given() || options.scale().factor() != 1
                || (long) options.width() * h != (long) options.height() * w
                || scale.times(w) != options.width() || scale.times(h) != options.height()
                || objects.stream().noneMatch(o -> inRegion(o.bounds(), camera, w, h))) {
            return "";
        }
        return "; or, to see at " + options.width() + "×" + options.height() + " what " + w + "×" + h + " shows, give "
                + "--scale " + scale + " in place of --width and --height";
    }

    /**
     * Whether {@code box} reaches, in front of the camera, into the part of the image plane that its rays leave
     * from: by Listing 4.1, offsets from −(w/2) to w − w/2 pixels (one more for the rays' spacing), over the zoom.
     */
    private static boolean inRegion(BoundingBox box, OrthographicCamera camera, int width, int height) {
        if (!box.isBounded()) {
            return true;
        }
        double zoom = camera.zoom();
        DoubleSummaryStatistics u = along(box, camera.position(), camera.widthVector());
        DoubleSummaryStatistics v = along(box, camera.position(), camera.heightVector());
        return u.getMax() >= -(width / 2) / zoom && u.getMin() <= (width - width / 2) / zoom
                && v.getMax() >= -(height / 2) / zoom && v.getMin() <= (height - height / 2) / zoom
                && !isBehind(box, camera.position(), camera.direction());
    }

    /** Whether every corner of {@code box} lies behind the plane through {@code position} facing {@code forward}. */
    private static boolean isBehind(BoundingBox box, Vector3f position, Vector3f forward) {
        return box.isBounded() && along(box, position, forward).getMax() < 0;
    }

    private static DoubleSummaryStatistics along(BoundingBox box, Vector3f origin, Vector3f axis) {
        Vector3f a = box.min();
        Vector3f b = box.max();
        return IntStream.range(0, 8).mapToObj(i -> new Vector3f((i & 1) == 0 ? a.x() : b.x(), (i & 2) == 0 ? a.y()
                : b.y(), (i & 4) == 0 ? a.z() : b.z())).mapToDouble(c -> c.subtract(origin).dot(axis))
                .summaryStatistics();
    }
}
