package rtd.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.withinPercentage;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.testing.GoldenImages;
import rtd.testing.ImageComparison;
import rtd.testing.Scenes;

/**
 * The paper's example (Listing A.1) at 1920×1080, drawn by the paper's own loop
 * ({@link Scene#render}): against the independent golden image, and against numbers worked
 * out by hand, so that a regenerated golden cannot hide a bug.
 */
@DisplayName("The paper's example scene (Listing A.1, Abbildung A.1)")
class PaperExampleTest {

    private static final int RED = 0xFF0000;
    private static final int BLUE = 0x007FFF;
    private static final int AMBIENT = 0x7FFFFF;
    private static BufferedImage image;

    @BeforeAll
    static void render() {
        image = Scenes.example("input_rtd").render(1920, 1080);
    }

    @Test
    void matchesTheIndependentGoldenImageWithinTheEdgeTolerance() {
        GoldenImages.assertMatchesGolden("input_rtd_1920x1080", image, ImageComparison.EDGE_TOLERANT);
    }

    @Test
    void theSphereCentresAreWhereTheCameraPutsThem() {
        // x = X·zoom + w/2 and y = −Y·zoom + h/2 for a camera at the origin looking along −z.
        assertThat(image.getRGB(-10 * 50 + 960, -1 * 50 + 540) & 0xFFFFFF).isEqualTo(RED);
        assertThat(image.getRGB(3 * 50 + 960, -8 * 50 + 540) & 0xFFFFFF).isEqualTo(BLUE);
    }

    @Test
    void pixelsAwayFromTheSpheresShowTheAmbientColour() {
        assertThat(image.getRGB(0, 0) & 0xFFFFFF).isEqualTo(AMBIENT);
        assertThat(image.getRGB(1919, 1079) & 0xFFFFFF).isEqualTo(AMBIENT);
        assertThat(image.getRGB(-10 * 50 + 960 + 5 * 50 + 2, 490) & 0xFFFFFF).isEqualTo(AMBIENT);
    }

    @Test
    void eachSphereCoversPiRSquaredZoomSquaredPixels() {
        assertThat(count(RED)).isCloseTo(Math.PI * 5 * 5 * 50 * 50, withinPercentage(1));
        assertThat(count(BLUE)).isCloseTo(Math.PI * 2 * 2 * 50 * 50, withinPercentage(1));
    }

    @Test
    void everyPixelIsOneOfTheThreeColours() {
        assertThat(count(RED) + count(BLUE) + count(AMBIENT)).isEqualTo(1920.0 * 1080);
    }

    private static double count(int rgb) {
        int n = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                n += (image.getRGB(x, y) & 0xFFFFFF) == rgb ? 1 : 0;
            }
        }
        return n;
    }
}
