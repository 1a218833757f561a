package rtd.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static rtd.testing.Scenes.frontCamera;
import static rtd.testing.Scenes.scene;
import static rtd.testing.Scenes.sphere;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.accel.Bvh;
import rtd.geometry.Sphere;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The depth test (section 3.2.3, Listing 4.3)")
class DepthTestTest {

    private static final int NEAR = 0x00FF00;
    private static final int FAR = 0xFF0000;
    private final Ray axis = new Ray(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1));
    private final Sphere near = sphere(0, 0, 5, 1, NEAR);
    private final Sphere far = sphere(0, 0, -5, 3, FAR);

    @Test
    void theNearerSphereWinsWhenItComesFirstInTheFile() {
        assertThat(scene(frontCamera(20, 10), near, far).trace(axis).getRGB()).isEqualTo(NEAR);
    }

    @Test
    void theNearerSphereWinsWhenItComesLastInTheFile() {
        assertThat(scene(frontCamera(20, 10), far, near).trace(axis).getRGB()).isEqualTo(NEAR);
    }

    @Test
    void onAnExactTieTheSphereFirstInTheFileWins() {
        Sphere first = sphere(0, 0, 0, 2, 0x0000FF);
        Sphere second = sphere(0, 0, 0, 2, 0xFFFF00);
        Scene scene = scene(frontCamera(20, 10), first, second);
        assertThat(scene.trace(axis).getRGB()).isEqualTo(0x0000FF);
        Bvh bvh = Bvh.build(scene);
        assertThat(bvh.newTracer().nearestHit(axis).index()).isZero();
        assertThat(scene.nearestHit(axis).index()).isZero();
    }

    @Test
    void aRayThatHitsNothingTakesTheAmbientColour() {
        Ray aside = new Ray(new Vector3f(50, 0, 20), new Vector3f(0, 0, -1));
        assertThat(scene(frontCamera(20, 10), near, far).trace(aside).getRGB()).isEqualTo(0xFFFFFF);
    }
}
