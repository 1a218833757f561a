package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;
import static rtd.accel.SameHit.assertSame;

import java.util.Random;
import java.util.function.Function;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.Shader;
import rtd.render.Tracer;
import rtd.scene.Scene;
import rtd.shade.FlatShader;
import rtd.shade.WhittedShader;
import rtd.testing.MixedScenes;
import rtd.testing.Renders;
import rtd.testing.TransformedScenes;

/**
 * Transformed and patterned objects, which the engine does not know, are found and drawn as the
 * paper's loop finds and draws them: the same hits for rays from anywhere, the same flat and
 * shaded pixels through the BVH, the view grid and the light grids.
 */
@DisplayName("The engine finds the loop's hits on transformed and patterned objects")
class TransformedEqualsLoopTest {

    private static final int WIDTH = 96;
    private static final int HEIGHT = 64;

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4})
    void forRandomRaysFromAnywhere(long seed) {
        Scene scene = TransformedScenes.of(MixedScenes.generate(seed, 60 + (int) (seed * 97 % 200)), seed);
        BvhTracer tracer = Bvh.build(scene).newTracer();
        Random random = new Random(seed);
        int hits = 0;
        for (int r = 0; r < 10_000; r++) {
            Ray ray = MixedScenes.ray(random, scene);
            Hit expected = scene.nearestHit(ray);
            assertSame(tracer.nearestHit(ray), expected, "ray " + r + " " + ray);
            hits += expected == null ? 0 : 1;
        }
        assertThat(hits).as("rays that hit something").isGreaterThan(1_000);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {5, 6})
    void inFlatColoursTheBvhAndTheGridDrawThePapersPixels(long seed) {
        Scene scene = TransformedScenes.of(MixedScenes.generate(seed, 120), seed);
        int[] paper = Renders.paper(scene, WIDTH, HEIGHT);
        assertThat(Renders.parallel(scene, WIDTH, HEIGHT, 2, true).image().rgb()).isEqualTo(paper);
        ViewGrid grid = ViewGrid.build(scene, WIDTH, HEIGHT, 1, 2);
        FlatShader flat = new FlatShader(scene);
        assertThat(ParallelRenderer.render(scene.camera(), grid::newTracer, tracer -> flat, WIDTH, HEIGHT, 2,
                new RenderProgress()).image().rgb()).isEqualTo(paper);
    }

    @ParameterizedTest(name = "random shaded scene {0}")
    @ValueSource(longs = {7, 8})
    void shadedTheGridsAndTheBvhDrawTheLoopsPixels(long seed) {
        Scene scene = TransformedScenes.of(MixedScenes.shaded(MixedScenes.generate(seed, 80), seed), seed);
        Function<Tracer, Shader> shaders = tracer -> new WhittedShader(scene, tracer);
        int[] loop = ParallelRenderer.render(scene.camera(), () -> new LinearTracer(scene), shaders, WIDTH, HEIGHT, 2,
                new RenderProgress()).image().rgb();
        Bvh bvh = Bvh.build(scene);
        ViewGrid grid = ViewGrid.build(scene, WIDTH, HEIGHT, 1, 2);
        LightGrids lights = LightGrids.build(scene, WIDTH, HEIGHT, 1, 2);
        assertThat(ParallelRenderer.render(scene.camera(), bvh::newTracer, shaders, WIDTH, HEIGHT, 2,
                new RenderProgress()).image().rgb()).isEqualTo(loop);
        assertThat(ParallelRenderer.render(scene.camera(), () -> grid.newTracer(lights.newTracer(bvh.newTracer())), shaders,
                WIDTH, HEIGHT, 2, new RenderProgress()).image().rgb()).isEqualTo(loop);
    }
}
