package rtd.scene;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.testing.GoldenImages;
import rtd.testing.ImageComparison;
import rtd.testing.Scenes;

/** rtd's own example scenes: exact goldens, each backed by pixels worked out by hand. */
@DisplayName("The example scenes of examples/")
class OwnExamplesTest {

    @ParameterizedTest(name = "{0} matches its golden image exactly")
    @ValueSource(strings = {"depth_test", "oblique_view", "image_border"})
    void matchesItsGoldenImageExactly(String name) {
        BufferedImage image = Scenes.example(name).render(1920, 1080);
        GoldenImages.assertMatchesGolden(name, image, ImageComparison.EXACT);
    }

    @Test
    void inDepthTestTheNearestSphereCoversTheOthers() {
        BufferedImage image = Scenes.example("depth_test").render(1920, 1080);
        // zoom 60: x = X·60 + 960, y = −Y·60 + 540
        assertThat(rgb(image, 1, 1)).as("blue, nearest, in front of green and orange").isEqualTo(0x1E5AC8);
        assertThat(rgb(image, 5, -4)).as("orange in front of green").isEqualTo(0xF08C14);
        assertThat(rgb(image, 0, -5)).as("green where nothing is in front").isEqualTo(0x28A050);
        assertThat(rgb(image, -7, 2)).as("purple, centre nearer than red's").isEqualTo(0x6E28A0);
        assertThat(rgb(image, -11, 5)).as("red, where purple does not reach").isEqualTo(0xC81E3C);
    }

    @Test
    void inImageBorderOnlyTheSpheresInViewAndInFrontShow() {
        BufferedImage image = Scenes.example("image_border").render(1920, 1080);
        int black = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                black += (image.getRGB(x, y) & 0xFFFFFF) == 0 ? 1 : 0;
            }
        }
        assertThat(black).as("pixels of the black spheres out of view and behind the camera").isZero();
        // zoom 40: the sphere around the image plane at x = 18 shows from the inside.
        assertThat(image.getRGB(18 * 40 + 960, 540) & 0xFFFFFF).isEqualTo(0x5AAA5A);
        assertThat(image.getRGB(0, 1079) & 0xFFFFFF).as("the corner sphere is cut by the border").isEqualTo(0xC83C28);
    }

    private static int rgb(BufferedImage image, float worldX, float worldY) {
        return image.getRGB(Math.round(worldX * 60 + 960), Math.round(-worldY * 60 + 540)) & 0xFFFFFF;
    }
}
