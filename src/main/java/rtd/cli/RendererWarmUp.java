package rtd.cli;

import rtd.accel.ViewGrid;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.scene.Scene;
import rtd.shade.FlatShader;

/**
 * Reads, builds and renders a tiny scene once, on the warm-up thread ({@link WriterWarmUp}),
 * so that the classes of the reader, the view grid and the renderer are loaded, and the grammar's
 * table is made, on a spare core while picocli starts, instead of on the way of the first
 * scene. None of its numbers are kept.
 */
final class RendererWarmUp {

    /** One statement of each of the paper's kinds, and a sphere in view. */
    static final String SCENE = """
            ambient:(127|255|255)
            orthographic_camera:(0|0|20):(0|0|-1):(50)
            sphere:(0|0|0):(0.1):(0|127|255)
            """;

    private RendererWarmUp() {
    }

    /** Renders {@link #SCENE} at 24 × 16 pixels on this thread; the run itself meets and reports any failure. */
    static void run() {
        try {
            Scene scene = SceneIO.parseScene("warm-up", SCENE);
            FlatShader flat = new FlatShader(scene);
            ViewGrid grid = ViewGrid.build(scene, 24, 16, 1, 1);
            ParallelRenderer.render(scene.camera(), grid::newTracer, tracer -> flat, 24, 16, 1, new RenderProgress());
        } catch (SceneException | RuntimeException e) {
            // only a warm-up: the run itself reads, builds and renders, and says what fails
        }
    }
}
