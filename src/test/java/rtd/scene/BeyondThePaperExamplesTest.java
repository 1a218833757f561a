package rtd.scene;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import rtd.accel.Bvh;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Sphere;
import rtd.image.Picture;
import rtd.math.Vector3f;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.shade.FlatShader;
import rtd.shade.WhittedShader;
import rtd.testing.GoldenImages;
import rtd.testing.ImageComparison;
import rtd.testing.Scenes;

/**
 * The examples beyond the paper (perspective, more shapes, meshes, light): exact goldens, each
 * backed by facts worked out by hand.
 */
@DisplayName("The examples beyond the paper")
class BeyondThePaperExamplesTest {

    /** The example rendered as the command line does: through the BVH (which equals the loop), shaded if it has lights. */
    static Picture render(String name, int width, int height) {
        return render(Scenes.example(name), width, height);
    }

    /**
     * The example as {@code --scale} draws it, the same view at {@code scale} times 1920 × 1080:
     * the orthographic camera's zoom scaled too (the perspective camera's view does not change).
     */
    static Picture renderAtScale(String name, double scale) {
        Scene scene = Scenes.example(name);
        if (scene.camera() instanceof OrthographicCamera camera) {
            scene = new Scene(scene.ambient(), new OrthographicCamera(camera.position(), camera.direction(),
                    (float) (camera.zoom() * scale)), scene.objects(), scene.lights());
        }
        return render(scene, (int) Math.round(1920 * scale), (int) Math.round(1080 * scale));
    }

    private static Picture render(Scene scene, int width, int height) {
        Bvh bvh = Bvh.build(scene);
        FlatShader flat = new FlatShader(scene);
        return ParallelRenderer.render(scene.camera(), bvh::newTracer,
                tracer -> scene.lights().isEmpty() ? flat : new WhittedShader(scene, tracer), width, height, 1, 2,
                new RenderProgress()).image();
    }

    /** The shaded examples at half the size (--scale 0.5), to keep the tests quick: the same view as the full picture. */
    @ParameterizedTest(name = "{0} at --scale {1} matches its golden image exactly")
    @CsvSource({"perspective_view, 1", "room, 1", "meshes, 1", "lit_paper, 0.5", "glass_and_mirror, 0.5", "smooth_mesh, 0.5"})
    void matchesItsGoldenImageExactly(String name, double scale) {
        GoldenImages.assertMatchesGolden(name, renderAtScale(name, scale).toBufferedImage(), ImageComparison.EXACT);
    }

    @Test
    void inPerspectiveTheNearerRedSphereGrowsAndTheFartherBlueOneShrinksLess() {
        Picture perspective = render("perspective_view", 1920, 1080);
        Picture orthographic = render("input_rtd", 1920, 1080);
        // Radius 5 at depth 15 from the eye: f = 960 / tan(44°) = 994 pixels, so 5 · 994 / 15 = 331 pixels wide
        // each way, against 5 · 50 = 250 in the paper's view; the blue one, radius 2 at depth 21: 95 against 100.
        int red = count(perspective, 0xFF0000);
        int blue = count(perspective, 0x007FFF);
        assertThat(count(orthographic, 0xFF0000)).isCloseTo((int) (Math.PI * 250 * 250), org.assertj.core.data.Percentage.withPercentage(1));
        assertThat((double) red).isGreaterThan(Math.PI * 300 * 300 * 0.5); // partly cut by the left border
        assertThat((double) blue).isCloseTo(Math.PI * 95 * 95, org.assertj.core.data.Offset.offset(Math.PI * 95 * 95 * 0.1));
    }

    @Test
    void inTheLitPaperSceneTheHighlightIsWhereTheNormalHalvesLightAndEye() {
        Scene scene = Scenes.example("lit_paper");
        Sphere red = (Sphere) scene.objects().get(1);
        Vector3f toLight = scene.lights().get(0).position().subtract(red.center()).normalize();
        Vector3f toEye = new Vector3f(0, 0, 1); // the orthographic camera looks along −z
        Vector3f peak = red.center().add(toLight.add(toEye).normalize().multiply(red.radius()));
        int x = Math.round(peak.x() * 50 + 960);
        int y = Math.round(-peak.y() * 50 + 540);
        Picture picture = render("lit_paper", 1920, 1080);
        int brightest = brightestRedPixel(picture);
        assertThat(Math.abs(brightest % 1920 - x)).as("x of the highlight").isLessThanOrEqualTo(3);
        assertThat(Math.abs(brightest / 1920 - y)).as("y of the highlight").isLessThanOrEqualTo(3);
        // The red sphere's far side, away from the light, gets the ambient term only: 0.1 · 255.
        assertThat(picture.rgb(960 - 10 * 50 - 240, 540 - 50)).isEqualTo(26 << 16);
    }

    @Test
    void inTheRoomEachWallShowsItsColourWhereTheCameraSeesIt() {
        Picture room = render("room", 1920, 1080);
        assertThat(room.rgb(960, 1050)).as("floor").isEqualTo(0xAA8C64);
        assertThat(room.rgb(20, 200)).as("left wall").isEqualTo(0xBE5A50);
        assertThat(room.rgb(1900, 200)).as("right wall").isEqualTo(0x506EAA);
        assertThat(room.rgb(1120, 60)).as("back wall").isEqualTo(0xDCDCCD);
    }

    private static int count(Picture picture, int rgb) {
        int n = 0;
        for (int value : picture.rgb()) {
            n += value == rgb ? 1 : 0;
        }
        return n;
    }

    private static int brightestRedPixel(Picture picture) {
        int best = -1;
        int bestGreen = -1;
        int[] rgb = picture.rgb();
        for (int i = 0; i < rgb.length; i++) {
            int r = rgb[i] >> 16 & 0xFF;
            int g = rgb[i] >> 8 & 0xFF;
            if (r == 255 && g > bestGreen && i % 1920 < 960) { // the red sphere's highlight whitens it
                bestGreen = g;
                best = i;
            }
        }
        return best;
    }
}
