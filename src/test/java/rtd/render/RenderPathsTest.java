package rtd.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.accel.Bvh;
import rtd.scene.Scene;
import rtd.testing.RandomScenes;
import rtd.testing.Scenes;

/**
 * The faster paths draw exactly the paper's picture: {@link ParallelRenderer} on any number
 * of threads, with the paper's loop or with the BVH, gives the same pixels as
 * {@link Scene#render}.
 */
@DisplayName("Every render path gives the paper's pixels")
class RenderPathsTest {

    static int[] pixels(BufferedImage image) {
        BufferedImage copy = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_RGB);
        copy.getGraphics().drawImage(image, 0, 0, null);
        return ((DataBufferInt) copy.getRaster().getDataBuffer()).getData();
    }

    static BufferedImage parallel(Scene scene, int w, int h, int threads, boolean bvh) {
        if (bvh) {
            Bvh hierarchy = Bvh.build(scene, w, h);
            return ParallelRenderer.render(scene.camera(), hierarchy::newTracer, w, h, threads, new RenderProgress()).image();
        }
        return ParallelRenderer.render(scene.camera(), () -> new LinearTracer(scene), w, h, threads,
                new RenderProgress()).image();
    }

    @ParameterizedTest(name = "{0} thread(s), paper's loop and BVH, on the paper's example")
    @ValueSource(ints = {1, 2, 3, 8})
    void anyThreadCountGivesThePapersPixels(int threads) {
        Scene scene = Scenes.example("input_rtd");
        int[] reference = pixels(scene.render(480, 270));
        assertThat(pixels(parallel(scene, 480, 270, threads, false))).isEqualTo(reference);
        assertThat(pixels(parallel(scene, 480, 270, threads, true))).isEqualTo(reference);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20})
    void theBvhGivesThePapersPixelsOnRandomScenes(long seed) {
        Scene scene = RandomScenes.generate(seed, 40 + (int) (seed * 37 % 300));
        int[] reference = pixels(scene.render(200, 150));
        assertThat(pixels(parallel(scene, 200, 150, 3, true))).isEqualTo(reference);
    }
}
