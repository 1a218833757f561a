package rtd.explain;

import rtd.camera.ICamera;
import rtd.camera.ImageAxes;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * Step 1 of an explanation: how the camera makes the ray of pixel (x, y) (section 3.2.1). The orthographic camera by
 * Listing 4.1, the perspective camera by its own formula; each intermediate number computed with the camera's own float
 * operations, in its order.
 */
final class RayGeneration {

    private RayGeneration() {
    }

    /** Writes the step into {@code text}; the ray is the camera's own, {@code ray}. */
    static void explain(Text text, ICamera camera, Ray ray, int x, int y, int w, int h) {
        int offsetX = x - (w / 2);
        int offsetY = y - (h / 2);
        if (camera instanceof OrthographicCamera orthographic) {
            text.line("1. Ray generation (section 3.2.1, Listing 4.1: OrthographicCamera.generateRay)").in();
            offsets(text, x, y, w, h, offsetX, offsetY);
            axes(text, orthographic.direction(), orthographic.widthVector(), orthographic.heightVector());
            Vector3f u = orthographic.widthVector();
            Vector3f v = orthographic.heightVector();
            float zoom = orthographic.zoom();
            text.line("O = pos + u·x'/zoom + v·y'/zoom = " + Numbers.of(orthographic.position()) + " + "
                    + Numbers.of(u.multiply(offsetX).divide(zoom)) + " + "
                    + Numbers.of(v.multiply(offsetY).divide(zoom))
                    + " = " + Numbers.of(ray.origin()) + "   (zoom " + Numbers.of(zoom) + ")");
            text.line(orthographic.target() == null
                    ? "R = dir, as the scene file gives it = " + Numbers.of(ray.direction())
                    : "R = dir = at − pos = "
                            + lookAt(orthographic.target(), orthographic.position(), ray.direction()));
        } else { // the only other camera a scene file makes
            PerspectiveCamera perspective = (PerspectiveCamera) camera;
            text.line("1. Ray generation (section 3.2.1; rtd's perspective camera: "
                    + "PerspectiveCamera.generateRay)").in();
            offsets(text, x, y, w, h, offsetX, offsetY);
            if (perspective.target() != null) {
                text.line("dir = at − pos = "
                        + lookAt(perspective.target(), perspective.position(), perspective.direction()));
            }
            axes(text, perspective.direction(), perspective.widthVector(), perspective.heightVector());
            float f = perspective.focalLength(w);
            text.line("f = (w/2) / tan(fov/2) = " + Numbers.of((float) (w / 2.0))
                    + " / tan(" + Numbers.of(perspective.fieldOfView())
                    + "°/2) = " + Numbers.of(f) + " pixels");
            text.line("O = pos = " + Numbers.of(ray.origin()));
            text.line("R = normalize(dir)·f + u·x' + v·y' = " + Numbers.of(perspective.direction().normalize()) + "·"
                    + Numbers.of(f) + " + u·" + offsetX + " + v·" + offsetY + " = " + Numbers.of(ray.direction()));
        }
        text.out();
    }

    private static void offsets(Text text, int x, int y, int w, int h, int offsetX, int offsetY) {
        text.line("x' = x − w/2 = " + x + " − " + (w / 2) + " = " + offsetX
                + "   (whole numbers: the ray leaves the pixel's corner)");
        text.line("y' = y − h/2 = " + y + " − " + (h / 2) + " = " + offsetY);
    }

    private static String lookAt(Vector3f target, Vector3f position, Vector3f direction) {
        return Numbers.of(target) + " − " + Numbers.of(position) + " = " + Numbers.of(direction)
                + "   (the camera looks at the point)";
    }

    private static void axes(Text text, Vector3f dir, Vector3f u, Vector3f v) {
        text.line(ImageAxes.looksStraightUpOrDown(dir)
                ? "u = " + Numbers.of(u)
                        + "   (right in the image: looking straight up or down, dir × (0,1,0) is zero, "
                        + "so world x is right, as ImageAxes.of says)"
                : "u = normalize(dir × (0,1,0)) = " + Numbers.of(u) + "   (right in the image)");
        text.line("v = normalize(dir × u) = " + Numbers.of(v) + "   (down in the image)");
    }
}
