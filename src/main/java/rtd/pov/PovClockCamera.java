package rtd.pov;

import static rtd.pov.PovClock.number;
import static rtd.pov.PovClock.vector;

import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.io.ClockFields;
import rtd.math.Vector3f;

/**
 * A camera whose numbers use the clock, in POV-Ray's words: its position and view direction (or the point it
 * looks at) are declared from their expressions, and the image's axes worked out from them as rtd's camera
 * does ({@code u = normalize(dir × (0,1,0))}, {@code v = normalize(dir × u)}, Listing 4.1), then the camera
 * written with explicit vectors and shifted from pixel centres to rtd's corners as {@link PovScene#camera}
 * writes a camera that stands still.
 */
final class PovClockCamera {

    private PovClockCamera() {
    }

    /** The declarations and the camera; {@code camera} is the camera at the reading's clock, for its kind and its fixed numbers. */
    static String of(ClockFields f, ICamera camera, int w, int h) {
        String shiftX = factor(w / 2.0 - w / 2 - 0.5);
        String shiftY = factor(h / 2.0 - h / 2 - 0.5);
        if (camera instanceof OrthographicCamera ortho) {
            String zoom = "(" + number(f, "zoom", 0, ortho.zoom()) + ")";
            return axes(f, ortho.position(), ortho.direction(), ortho.target()) + "camera {\n  orthographic\n"
                    + "  location Rtd_position + Rtd_right * " + shiftX + " / " + zoom + " + Rtd_down * " + shiftY + " / " + zoom
                    + "\n  direction Rtd_view\n  right Rtd_right * " + w + " / " + zoom + "\n  up Rtd_down * " + factor(-h) + " / "
                    + zoom + "\n}\n";
        }
        PerspectiveCamera perspective = (PerspectiveCamera) camera;
        String fov = number(f, "field of view", 0, perspective.fieldOfView());
        return axes(f, perspective.position(), perspective.direction(), perspective.target())
                + "camera {\n  perspective\n  location Rtd_position\n  direction vnormalize(Rtd_view) * " + PovNumbers.num(w / 2.0)
                + " / tan(radians(" + fov + ") / 2) + Rtd_right * " + shiftX + " + Rtd_down * " + shiftY
                + "\n  right Rtd_right * " + w + "\n  up Rtd_down * " + factor(-h) + "\n}\n";
    }

    /** The camera's position, view direction and image axes u (right) and v (down), declared for POV-Ray's clock. */
    private static String axes(ClockFields f, Vector3f position, Vector3f direction, Vector3f target) {
        String view = target != null ? vector(f, "view direction", target) + " - Rtd_position"
                : vector(f, "view direction", direction);
        return "#declare Rtd_position = " + vector(f, "position", position) + ";\n#declare Rtd_view = " + view + ";\n"
                + "#declare Rtd_right = vnormalize(vcross(Rtd_view, <0, 1, 0>));\n"
                + "#declare Rtd_down = vnormalize(vcross(Rtd_view, Rtd_right));\n";
    }

    /** A number to multiply by, in parentheses if it is negative: {@code v * (-0.5)}. */
    private static String factor(double value) {
        String text = PovNumbers.num(value);
        return value < 0 ? "(" + text + ")" : text;
    }
}
