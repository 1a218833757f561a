package rtd.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.withinPercentage;
import static rtd.testing.Scenes.scene;
import static rtd.testing.Scenes.sphere;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.ImageComparison;
import rtd.testing.Renders;
import rtd.image.Picture;

@DisplayName("Pictures worked out by hand")
class HitPixelCountTest {

    private static long count(BufferedImage image, int rgb) {
        long n = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                n += (image.getRGB(x, y) & 0xFFFFFF) == rgb ? 1 : 0;
            }
        }
        return n;
    }

    @Test
    void aSphereCoversPiRSquaredZoomSquaredPixels() {
        Scene scene = scene(new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 40),
                sphere(1.5f, -2, 0, 3, 0xFF0000));
        assertThat((double) count(scene.render(1920, 1080), 0xFF0000)).isCloseTo(Math.PI * 9 * 40 * 40, withinPercentage(1));
    }

    @Test
    void anObliqueViewShowsASphereAsACircleOfTheSameArea() {
        Scene scene = scene(new OrthographicCamera(new Vector3f(10, 7, 10), new Vector3f(-1, -0.7f, -1), 30),
                sphere(0, 0, 0, 4, 0x00FF00));
        assertThat((double) count(scene.render(640, 480), 0x00FF00)).isCloseTo(Math.PI * 16 * 30 * 30, withinPercentage(1));
    }

    @Test
    void aDirectionScaledByAPowerOfTwoGivesTheIdenticalPicture() {
        Scene unit = scene(new OrthographicCamera(new Vector3f(10, 7, 10), new Vector3f(-1, -1, -1), 30),
                sphere(0, 0, 0, 4, 0x00FF00), sphere(2, 2, 2, 1, 0x0000FF));
        Scene scaled = new Scene(unit.ambient(),
                new OrthographicCamera(new Vector3f(10, 7, 10), new Vector3f(-4, -4, -4), 30), unit.objects());
        assertThat(Renders.paper(scaled, 320, 240)).isEqualTo(Renders.paper(unit, 320, 240));
    }

    @Test
    void anUnnormalisedDirectionGivesTheNormalisedOnesPictureUpToRounding() {
        Vector3f direction = new Vector3f(-3, -2, -5);
        Scene raw = scene(new OrthographicCamera(new Vector3f(12, 8, 20), direction, 30),
                sphere(0, 0, 0, 4, 0x00FF00), sphere(2, 2, 2, 1, 0x0000FF));
        Scene normalised = new Scene(raw.ambient(),
                new OrthographicCamera(new Vector3f(12, 8, 20), direction.normalize(), 30), raw.objects());
        ImageComparison.Result result = ImageComparison.EDGE_TOLERANT.compare(raw.render(320, 240), normalised.render(320, 240));
        assertThat(result.matches()).as(result.summary()).isTrue();
    }

    @Test
    void lookingStraightDownGivesAPictureNotNaN() {
        Scene scene = scene(new OrthographicCamera(new Vector3f(0, 10, 0), new Vector3f(0, -1, 0), 20),
                sphere(0, 0, 0, 2, 0xFF0000), sphere(3, 0, -3, 1, 0x0000FF));
        BufferedImage image = scene.render(200, 200);
        assertThat(image.getRGB(100, 100) & 0xFFFFFF).isEqualTo(0xFF0000);
        // World x points right and −z up: the blue sphere at (3, 0, −3) is up and to the right.
        assertThat(image.getRGB(100 + 60, 100 - 60) & 0xFFFFFF).isEqualTo(0x0000FF);
        assertThat((double) count(image, 0xFF0000)).isCloseTo(Math.PI * 4 * 400, withinPercentage(2));
    }
}
