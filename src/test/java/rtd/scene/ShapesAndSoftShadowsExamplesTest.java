package rtd.scene;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.image.Color;
import rtd.image.Picture;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.shade.WhittedShader;
import rtd.testing.GoldenImages;
import rtd.testing.ImageComparison;
import rtd.testing.Scenes;

/** The examples of cylinders, cones and soft shadows: exact goldens at --scale 0.5, each backed by facts worked out by hand. */
@DisplayName("The examples of the new shapes and soft shadows")
class ShapesAndSoftShadowsExamplesTest {

    @ParameterizedTest(name = "{0} at --scale 0.5 matches its golden image exactly")
    @ValueSource(strings = {"shapes", "soft_shadows"})
    void matchesItsGoldenImageExactly(String name) {
        GoldenImages.assertMatchesGolden(name, BeyondThePaperExamplesTest.renderAtScale(name, 0.5).toBufferedImage(),
                ImageComparison.EXACT);
    }

    /**
     * At --scale 0.5 the front view is 960 × 540 at zoom 25: pixel (x, y) looks along −z from
     * ((x − 480)/25 | −(y − 270)/25 | 20). The column's axis, x = −6, is pixel 330: its side faces
     * the camera there, N = (0|0|1), and the far light at (−5000|5000|10000) gives
     * N·L = 9998/|(−4994|5000|9998)| = 0.81661; matt, so (0.1 + 0.9·0.81661)·(200|60|40) =
     * 0.83494·(200|60|40) = (167|50|33). In row 270 (y = 0) the cone, radius 2.5 at y = −3 and 0 at
     * y = 3, is 1.25 wide each way of x = 3: x from 1.75 to 4.25, pixels 524 to 586, 63 of them, lit or
     * in its own shadow.
     */
    @Test
    void theColumnFacingTheCameraAndTheConesWidthAreWhereGeometrySays() {
        Picture picture = BeyondThePaperExamplesTest.renderAtScale("shapes", 0.5);
        assertThat(Color.fromRGB(picture.rgb(330, 270))).isEqualTo(new Color(167, 50, 33));
        int blue = 0;
        for (int x = 0; x < 960; x++) {
            int rgb = picture.rgb(x, 270);
            if ((rgb & 0xFF) > (rgb >> 16 & 0xFF)) { // bluer than red: the cone, lit or not; the wall is warm grey
                blue++;
                assertThat(x).as("a pixel of the cone").isBetween(524, 586);
            }
        }
        assertThat(blue).isEqualTo(63);
    }

    /**
     * Under the red sphere, at (0.5|0|0), each of the 16 samples' shadow rays (towards x, z of
     * ±0.25, ±0.75 at y = 8) runs within 0.6 of the sphere's centre: all in shadow, the ambient term
     * alone, 0.1·200/255 = 0.0784: grey 20. At (6|0|−6), far from every object, all 16 are lit:
     * seen from straight above, the floor gets 0.1·c + Σ (0.9·c·N·L + 0.9·(N·L)^200)/16 with c =
     * 200/255 and N·L from 0.64 to 0.73 (0.68567 on average): 0.56243, grey 143. Between the two,
     * the penumbra.
     */
    @Test
    void theFloorIsDarkUnderTheSphereAndFullyLitFarFromIt() {
        Scene scene = Scenes.example("soft_shadows");
        WhittedShader shader = new WhittedShader(scene, new LinearTracer(scene));
        assertThat(scene.lights()).hasSize(16);
        assertThat(shade(shader, new Vector3f(0.5f, 0, 0))).isEqualTo(new Color(20, 20, 20));
        assertThat(shade(shader, new Vector3f(6, 0, -6))).isEqualTo(new Color(143, 143, 143));
    }

    /** The colour of the floor point {@code p} seen from straight above it, from between the floor and the light. */
    private static Color shade(WhittedShader shader, Vector3f p) {
        return shader.colourAt(new Ray(new Vector3f(p.x(), 0.01f, p.z()), new Vector3f(0, -1, 0)), WhittedShader.BOUNCES)
                .toColor();
    }
}
