package rtd.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.accel.Bvh;
import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.math.Vector3f;
import rtd.image.Color;
import rtd.scene.Scene;
import rtd.testing.RandomScenes;
import rtd.testing.Renders;
import rtd.testing.Scenes;

/**
 * The faster paths draw exactly the paper's picture: {@link ParallelRenderer} on any number
 * of threads, with the paper's loop or with the BVH, gives the same pixels as
 * {@link Scene#render}.
 */
@DisplayName("Every render path gives the paper's pixels")
class RenderPathsTest {

    static int[] pixels(Scene scene, int w, int h, int threads, boolean bvh) {
        return Renders.parallel(scene, w, h, threads, bvh).image().rgb();
    }

    @ParameterizedTest(name = "{0} thread(s), paper's loop and BVH, on the paper's example")
    @ValueSource(ints = {1, 2, 3, 8})
    void anyThreadCountGivesThePapersPixels(int threads) {
        Scene scene = Scenes.example("input_rtd");
        int[] reference = Renders.paper(scene, 480, 270);
        assertThat(pixels(scene, 480, 270, threads, false)).isEqualTo(reference);
        assertThat(pixels(scene, 480, 270, threads, true)).isEqualTo(reference);
    }

    @Test
    void theBandsAreTakenInAScatteredOrderEachOnce() {
        for (int bands = 1; bands <= 2_500; bands++) { // up to 20,000 rows
            boolean[] taken = new boolean[bands];
            for (int k = 0; k < bands; k++) {
                int band = ParallelRenderer.bandTaken(k, bands);
                assertThat(taken[band]).as("band %d of %d taken twice", band, bands).isFalse();
                taken[band] = true;
            }
        }
        // 1080 rows are 135 bands of 8: the step is 52 (135 · 0.382 = 51.6, and 52 has no factor
        // in common with 135 = 3³ · 5), so the bands come 0, 52, 104, 21, 73, 125, ...: the second
        // two fifths of the way down the picture, the third beyond three quarters.
        assertThat(ParallelRenderer.scatteringStep(135)).isEqualTo(52);
        assertThat(List.of(0, 1, 2, 3, 4, 5).stream().map(k -> ParallelRenderer.bandTaken(k, 135)))
                .containsExactly(0, 52, 104, 21, 73, 125);
        assertThat(ParallelRenderer.scatteringStep(1)).isEqualTo(1);
    }

    @ParameterizedTest(name = "height {0}")
    @ValueSource(ints = {1, 7, 9, 1081})
    void everyRowIsRenderedOnceAtAnyHeightAsThePapersLoopDrawsIt(int height) {
        Scene scene = Scenes.example("input_rtd");
        RenderProgress progress = new RenderProgress();
        int[] pixels = ParallelRenderer.render(scene.camera(), () -> new LinearTracer(scene),
                tracer -> new rtd.shade.FlatShader(scene), 13, height, 3, progress).image().rgb();
        assertThat(pixels).isEqualTo(Renders.paper(scene, 13, height));
        assertThat(progress.rowsDone()).isEqualTo(height);
    }

    @ParameterizedTest(name = "view direction {0}")
    @ValueSource(strings = {"0.0001 0 -1", "0 0 -1", "0 -0.5 2", "0.3 -0.7 -1.1"})
    @DisplayName("the BVH gives the paper's pixels where rounding noise is larger than the spheres")
    void theBvhKeepsEveryHitThatRoundingAdds(String direction) {
        // From 2,000 units away, float rounding moves a sphere's edge by more than its radius;
        // the paper's loop draws that noise, so the BVH must draw the very same noise.
        Random random = new Random(99);
        List<IGeometry> spheres = new ArrayList<>();
        for (int i = 0; i < 400; i++) {
            spheres.add(Scenes.sphere((random.nextFloat() - 0.5f) * 1.6f, (random.nextFloat() - 0.5f) * 1.2f,
                    (random.nextFloat() - 0.5f) * 10, 0.002f + random.nextFloat() * 0.03f, random.nextInt(0x1000000)));
        }
        String[] d = direction.split(" ");
        Vector3f view = new Vector3f(Float.parseFloat(d[0]), Float.parseFloat(d[1]), Float.parseFloat(d[2]));
        Vector3f position = new Vector3f(0.3f, -0.2f, 0).subtract(view.normalize().multiply(2000));
        Scene scene = new Scene(Color.BLACK, new OrthographicCamera(position, view, 100), spheres);
        int[] reference = Renders.paper(scene, 160, 120);
        assertThat(pixels(scene, 160, 120, 2, true)).isEqualTo(reference);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20})
    void theBvhGivesThePapersPixelsOnRandomScenes(long seed) {
        Scene scene = RandomScenes.generate(seed, 40 + (int) (seed * 37 % 300));
        int[] reference = Renders.paper(scene, 200, 150);
        assertThat(pixels(scene, 200, 150, 3, true)).isEqualTo(reference);
    }
}
