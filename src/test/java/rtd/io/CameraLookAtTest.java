package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.math.Ray;
import rtd.math.Vector3f;

/** {@code (at x|y|z)} in place of a camera's direction: the direction is that point minus the position. */
@DisplayName("A camera that looks at a point")
class CameraLookAtTest {

    private static Ray ray(String camera, int x, int y, int w, int h) throws SceneException {
        return SceneIO.parseScene("scene.txt", camera + "\n").camera().generateRay(x, y, w, h);
    }

    /**
     * From (3|0|0) at the origin: dir = (−3|0|0), u = normalize(dir × (0|1|0)) = (0|0|−1),
     * v = normalize(dir × u) = (0|−1|0). For 4 × 2 pixels and fov 90°, f = 2 / tan 45° = 2; pixel
     * (0|0) has x' = −2, y' = −1: R = (−1|0|0)·2 + (0|0|−1)·(−2) + (0|−1|0)·(−1) = (−2|1|2).
     */
    @Test
    void thePerspectiveCameraAimsAtThePoint() throws SceneException {
        Ray ray = ray("perspective_camera:(3|0|0):(at 0|0|0):(90)", 0, 0, 4, 2);
        assertThat(ray.origin()).isEqualTo(new Vector3f(3, 0, 0));
        assertThat(ray.direction().x()).isCloseTo(-2f, org.assertj.core.data.Offset.offset(1e-6f));
        assertThat(ray.direction().y()).isCloseTo(1f, org.assertj.core.data.Offset.offset(1e-6f));
        assertThat(ray.direction().z()).isCloseTo(2f, org.assertj.core.data.Offset.offset(1e-6f));
    }

    /**
     * From (0|5|0) straight down at the origin: dir = (0|−5|0), u falls back to (1|0|0), v =
     * normalize(dir × u) = (0|0|1). Pixel (0|0) of 20 × 10 at zoom 10: origin = pos + u·(−10)/10 +
     * v·(−5)/10 = (−1|5|−0.5), direction (0|−5|0).
     */
    @Test
    void theOrthographicCameraAimsAtThePoint() throws SceneException {
        Ray ray = ray("orthographic_camera:(0|5|0):(at 0|0|0):(10)", 0, 0, 20, 10);
        assertThat(ray.origin()).isEqualTo(new Vector3f(-1, 5, -0.5f));
        assertThat(ray.direction()).isEqualTo(new Vector3f(0, -5, 0));
    }

    @Test
    void eachCameraKeepsItsPointAndTheDirectionItMakes() throws SceneException {
        var perspective = (PerspectiveCamera) SceneIO.parseScene("s", "perspective_camera:(0|3|10):( at  0|1|0 ):(60)").camera();
        assertThat(perspective.target()).isEqualTo(new Vector3f(0, 1, 0));
        assertThat(perspective.direction()).isEqualTo(new Vector3f(0, -2, -10));
        var orthographic = (OrthographicCamera) SceneIO.parseScene("s", "orthographic_camera:(1|2|3):(at 1|2|0):(50)").camera();
        assertThat(orthographic.target()).isEqualTo(new Vector3f(1, 2, 0));
        assertThat(orthographic.direction()).isEqualTo(new Vector3f(0, 0, -3));
    }

    @Test
    void aPointAtTheCamerasPositionIsAMistakeAtThePoint() {
        SceneException e = catchThrowableOfType(SceneException.class,
                () -> SceneIO.parseScene("scene.txt", "perspective_camera:(0|0|10):(at 0|0|10):(60)\n"));
        assertThat(e.errors()).hasSize(1);
        assertThat(e.errors().get(0).column()).isEqualTo(33);
        assertThat(e.errors().get(0).message()).isEqualTo("the camera cannot look at its own position (at 0|0|10)");
    }

    @Test
    void aPointTooNearThePositionForFloatIsAMistake() {
        SceneException e = catchThrowableOfType(SceneException.class,
                () -> SceneIO.parseScene("scene.txt", "orthographic_camera:(0|0|0):(at 0|0|1e-30):(50)\n"));
        assertThat(e.errors().get(0).message()).contains("too near the camera's position");
    }
}
