package rtd.cli;

import java.util.concurrent.CompletableFuture;
import rtd.accel.Accelerator;
import rtd.io.ImageFormat;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.scene.Scene;
import rtd.shade.FlatShader;

/**
 * The one warm-up per JVM of {@code javax.imageio}, the reader, the view grid and the renderer on a tiny scene,
 * started before the command line is parsed, so that classes load on a spare core while picocli starts.
 */
final class WarmUp {

    /** One statement of each of the paper's kinds, and a sphere in view. */
    static final String SCENE = """
            ambient:(127|255|255)
            orthographic_camera:(0|0|20):(0|0|-1):(50)
            sphere:(0|0|0):(0.1):(0|127|255)
            """;

    private static CompletableFuture<Void> started;

    /** Starts the warm-up for {@code format}, unless one has started: the writers share most of what they load. */
    static synchronized CompletableFuture<Void> start(ImageFormat format) {
        if (started == null) {
            started = format.warmUp(WarmUp::renderOnce);
        }
        return started;
    }

    /** Renders {@link #SCENE} at 24 × 16 pixels on this thread; the run itself meets and reports any failure. */
    static void renderOnce() {
        try {
            Scene scene = SceneIO.parseScene("warm-up", SCENE);
            ParallelRenderer.render(scene.camera(), Accelerator.build(Accelerator.Kind.GRID, scene, 24, 16, 1, 1,
                    new Accelerator.StructureCache()).tracers(),
                    tracer -> new FlatShader(scene), 24, 16, 1, new RenderProgress());
        } catch (SceneException | RuntimeException e) {
            // only a warm-up: the run itself reads, builds and renders, and says what fails
        }
    }
}
