package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.Scenes;

@DisplayName("The point the camera orbits around")
class PivotTest {

    @Test
    void itIsWhatTheCentrePixelSees() {
        // from (0, 0, 20) along −z, the centre ray hits the sphere of radius 2 at (0, 0, 0) on its front, z = 2
        Scene scene = Scenes.scene(Scenes.frontCamera(20, 50), Scenes.sphere(0, 0, 0, 2, 0xFF0000));
        assertThat(CameraController.pivot(scene, 160, 90)).isEqualTo(new Vector3f(0, 0, 2));
    }

    @Test
    void whereTheCentreSeesNothingItIsTheMiddleOfTheObjectsBox() {
        // the paper's spheres: (3, 8, −1) radius 2 and (−10, 1, 5) radius 5 lie in the box (−15, −4, −3) to (5, 10,
        // 10), whose centre is (−5, 3, 3.5); the centre ray at x = y = 0 misses both. (The shapes' boxes are a
        // little larger, a margin for float's rounding.)
        Vector3f pivot = CameraController.pivot(Scenes.example("input_rtd"), 1920, 1080);
        assertThat(pivot.subtract(new Vector3f(-5, 3, 3.5f)).magnitude()).isLessThan(0.01f);
    }
}
