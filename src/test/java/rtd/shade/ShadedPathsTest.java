package rtd.shade;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.accel.Bvh;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.scene.Scene;
import rtd.testing.MixedScenes;
import rtd.testing.Renders;
import rtd.testing.Scenes;

/** Shaded pictures and samples are the same for any number of threads, with the paper's loop or the BVH. */
@DisplayName("Shading and samples on every render path")
class ShadedPathsTest {

    private static RenderResult render(Scene scene, int w, int h, int samples, int threads, boolean bvh) {
        Bvh hierarchy = bvh ? Bvh.build(scene) : null;
        return ParallelRenderer.render(scene.camera(), bvh ? hierarchy::newTracer : () -> new LinearTracer(scene),
                tracer -> new WhittedShader(scene, tracer), w, h, samples, threads, new RenderProgress());
    }

    @ParameterizedTest(name = "random shaded scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 6, 9}) // seeds whose lights some pixel faces: shadow rays are cast
    void theSamePixelsForAnyThreadCountWithAndWithoutTheBvh(long seed) {
        Scene scene = MixedScenes.shaded(MixedScenes.generate(seed, 60), seed);
        int[] reference = render(scene, 96, 64, 1, 1, false).image().rgb();
        assertThat(render(scene, 96, 64, 1, 3, false).image().rgb()).isEqualTo(reference);
        assertThat(render(scene, 96, 64, 1, 1, true).image().rgb()).isEqualTo(reference);
        RenderResult withBvh = render(scene, 96, 64, 1, 2, true);
        assertThat(withBvh.image().rgb()).isEqualTo(reference);
        assertThat(withBvh.work().secondaryRays().get("shadow")).isPositive();
        assertThat(withBvh.work().cameraRays()).isEqualTo(96 * 64);
    }

    @ParameterizedTest(name = "random shaded scene {0}")
    @ValueSource(longs = {7, 8})
    void samplesAreTheSameForAnyThreadCountWithAndWithoutTheBvh(long seed) {
        Scene scene = MixedScenes.shaded(MixedScenes.generate(seed, 60), seed);
        int[] reference = render(scene, 64, 48, 3, 1, false).image().rgb();
        assertThat(render(scene, 64, 48, 3, 2, true).image().rgb()).isEqualTo(reference);
    }

    @Test
    void oneSampleIsThePapersRayThroughTheCorner() {
        Scene scene = Scenes.example("input_rtd");
        int[] paper = Renders.paper(scene, 480, 270);
        FlatShader flat = new FlatShader(scene);
        int[] sampled = ParallelRenderer.render(scene.camera(), Bvh.build(scene)::newTracer, tracer -> flat, 480, 270, 1, 2,
                new RenderProgress()).image().rgb();
        assertThat(sampled).isEqualTo(paper);
    }

    @Test
    void twoByTwoSamplesAverageAFlatEdgeAndLeaveTheInsideAlone() {
        // One huge red sphere whose edge runs (nearly straight) down the middle of pixel column 10.
        List<IGeometry> objects = List.of(new Sphere(new Vector3f(-1000, 0, 0), 1000.5f, new Color(255, 0, 0)));
        Scene scene = new Scene(Color.BLACK, Scenes.frontCamera(20, 1), objects);
        FlatShader flat = new FlatShader(scene);
        int[] pixels = ParallelRenderer.render(scene.camera(), () -> new LinearTracer(scene), tracer -> flat, 20, 4, 2, 1,
                new RenderProgress()).image().rgb();
        // Pixel x covers world x from x − 10 to x − 9; the samples sit at x − 10 + 0.25 and + 0.75.
        assertThat(pixels[20 + 5]).isEqualTo(0xFF0000); // inside
        assertThat(pixels[20 + 15]).isEqualTo(0x000000); // outside
        // Column 10: world 0 to 1, the edge at 0.5: the samples at 0.25 hit, at 0.75 miss: half red, 127.5 rounded up.
        assertThat(pixels[20 + 10]).isEqualTo(0x800000);
        assertThat(pixels[20 + 9]).isEqualTo(0xFF0000);
        assertThat(pixels[20 + 11]).isEqualTo(0x000000);
    }
}
