package rtd.pov;

import static rtd.pov.PovClock.number;
import static rtd.pov.PovNumbers.num;
import static rtd.pov.PovNumbers.d;
import static rtd.pov.PovNumbers.plus;
import static rtd.pov.PovNumbers.times;
import static rtd.pov.PovNumbers.vector;

import rtd.camera.ICamera;
import rtd.camera.ImageAxes;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.io.ClockedScene.ClockFields;
import rtd.math.Vector3f;

/**
 * rtd's camera in POV-Ray's words: explicit vectors, POV-Ray's {@code right} along rtd's u and its {@code up} against
 * rtd's v, so no handedness rule of POV-Ray's {@code look_at} applies, shifted from POV-Ray's pixel centres to rtd's
 * corners. A camera whose numbers use the clock has its position and view direction (or the point it looks at)
 * declared from their expressions, and its axes worked out as rtd's are ({@code u = normalize(dir × (0,1,0))},
 * {@code v = normalize(dir × u)}, Listing 4.1).
 */
final class PovCamera {

    private PovCamera() {
    }

    /**
     * The camera, shifted from pixel centres to rtd's corners: {@code x' = x − ⌊w/2⌋} against POV-Ray's
     * {@code x + ½ − w/2}, a shift of {@code w/2 − ⌊w/2⌋ − ½} pixels (−½ for even w). A camera that looks at a point
     * gets POV-Ray's {@code look_at}: the orthographic one last, giving the same vectors again, the perspective one
     * as a comment, since there it would undo the shift.
     */
    static String of(ICamera camera, int w, int h) {
        double shiftX = w / 2.0 - w / 2 - 0.5;
        double shiftY = h / 2.0 - h / 2 - 0.5;
        if (camera instanceof OrthographicCamera ortho) {
            double zoom = ortho.zoom();
            double[] location = plus(plus(d(ortho.position()), times(d(ortho.widthVector()), shiftX / zoom)),
                    times(d(ortho.heightVector()), shiftY / zoom));
            // POV-Ray's look_at takes its right axis from sky × direction, which is zero looking straight up or down
            String lookAt = ortho.target() == null || ImageAxes.looksStraightUpOrDown(ortho.direction()) ? ""
                    : "\n  look_at " + vector(plus(location, d(ortho.direction())));
            return "camera {\n  orthographic\n  location " + vector(location)
                    + "\n  direction " + vector(d(ortho.direction()))
                    + "\n  right " + vector(times(d(ortho.widthVector()), w / zoom))
                    + "\n  up " + vector(times(d(ortho.heightVector()), -h / zoom)) + lookAt + "\n}\n";
        }
        PerspectiveCamera perspective = (PerspectiveCamera) camera; // the only other camera a scene file makes
        double f = w / 2.0 / Math.tan(Math.toRadians(perspective.fieldOfView()) / 2);
        double[] forward = d(perspective.direction().normalize());
        double[] direction = plus(plus(times(forward, f), times(d(perspective.widthVector()), shiftX)),
                times(d(perspective.heightVector()), shiftY));
        String lookAt = perspective.target() == null ? "" : "\n  // look_at " + vector(d(perspective.target()))
                + ", written out: POV-Ray's look_at would undo the half-pixel shift in direction";
        return "camera {\n  perspective\n  location " + vector(d(perspective.position())) + lookAt + "\n  direction "
                + vector(direction) + "\n  right " + vector(times(d(perspective.widthVector()), w))
                + "\n  up " + vector(times(d(perspective.heightVector()), -h)) + "\n}\n";
    }

    /** The declarations and the camera; {@code camera} is the camera at the reading's clock, for its fixed numbers. */
    static String withClock(ClockFields f, ICamera camera, int w, int h) {
        String shiftX = factor(w / 2.0 - w / 2 - 0.5);
        String shiftY = factor(h / 2.0 - h / 2 - 0.5);
        if (camera instanceof OrthographicCamera ortho) {
            String zoom = "(" + number(f, "zoom", 0, ortho.zoom()) + ")";
            return axes(f, ortho.position(), ortho.direction(), ortho.target()) + "camera {\n  orthographic\n"
                    + "  location Rtd_position + Rtd_right * " + shiftX + " / " + zoom
                    + " + Rtd_down * " + shiftY + " / " + zoom
                    + "\n  direction Rtd_view\n  right Rtd_right * " + w + " / " + zoom
                    + "\n  up Rtd_down * " + factor(-h) + " / "
                    + zoom + "\n}\n";
        }
        PerspectiveCamera perspective = (PerspectiveCamera) camera;
        String fov = number(f, "field of view", 0, perspective.fieldOfView());
        return axes(f, perspective.position(), perspective.direction(), perspective.target())
                + "camera {\n  perspective\n  location Rtd_position\n  direction vnormalize(Rtd_view) * "
                + PovNumbers.num(w / 2.0)
                + " / tan(radians(" + fov + ") / 2) + Rtd_right * " + shiftX + " + Rtd_down * " + shiftY
                + "\n  right Rtd_right * " + w + "\n  up Rtd_down * " + factor(-h) + "\n}\n";
    }

    /** The camera's position, view direction and image axes u (right) and v (down), declared. */
    private static String axes(ClockFields f, Vector3f position, Vector3f direction, Vector3f target) {
        String view = target != null ? PovClock.vector(f, "view direction", target) + " - Rtd_position"
                : PovClock.vector(f, "view direction", direction);
        return "#declare Rtd_position = " + PovClock.vector(f, "position", position)
                + ";\n#declare Rtd_view = " + view + ";\n"
                + "#declare Rtd_right = vnormalize(vcross(Rtd_view, <0, 1, 0>));\n"
                + "#declare Rtd_down = vnormalize(vcross(Rtd_view, Rtd_right));\n";
    }

    /** A number to multiply by, in parentheses if it is negative: {@code v * (-0.5)}. */
    private static String factor(double value) {
        String text = PovNumbers.num(value);
        return value < 0 ? "(" + text + ")" : text;
    }
}
