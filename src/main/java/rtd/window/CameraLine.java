package rtd.window;

import java.math.BigDecimal;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.math.Vector3f;

/**
 * The window's camera as a line of a scene file, {@code perspective_camera:(pos):(dir):(fov)} or
 * {@code orthographic_camera:(pos):(dir):(zoom)}, ready to paste in place of the file's camera: each number is written
 * as a plain decimal that reads back as the very same float, so the scene with this line renders the window's picture
 * at the window's size, pixel for pixel.
 */
final class CameraLine {

    private CameraLine() {
    }

    static String of(ICamera camera) {
        if (camera instanceof PerspectiveCamera p) {
            return line("perspective_camera", p.position(), p.direction(), p.fieldOfView());
        }
        if (camera instanceof OrthographicCamera o) {
            return line("orthographic_camera", o.position(), o.direction(), o.zoom());
        }
        throw new IllegalArgumentException("no scene line for a " + camera.getClass().getSimpleName());
    }

    private static String line(String statement, Vector3f position, Vector3f direction, float last) {
        return statement + ":" + vector(position) + ":" + vector(direction) + ":(" + number(last) + ")";
    }

    private static String vector(Vector3f v) {
        return "(" + number(v.x()) + "|" + number(v.y()) + "|" + number(v.z()) + ")";
    }

    /** The shortest decimal that reads back as {@code value} (Java's own), without an exponent. */
    static String number(float value) {
        return new BigDecimal(Float.toString(value)).stripTrailingZeros().toPlainString();
    }
}
