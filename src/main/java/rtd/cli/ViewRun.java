package rtd.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.function.Supplier;
import rtd.io.ImageFormat;
import rtd.io.SceneIO;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.render.Tracer;
import rtd.scene.Scene;
import rtd.view.View;
import rtd.view.ViewPicture;
import rtd.view.ViewShader;

/**
 * {@code --view KIND}: renders what the camera's rays did ({@link View}) on the path the picture
 * would take (the paper's loop, the BVH or the view grid, all threads), and writes it in the format
 * of its name's extension (PNG by default), its scale on standard error.
 */
final class ViewRun {

    private ViewRun() {
    }

    /**
     * The view's picture, the work its rays took, and the accelerator they took it on (null for
     * {@code --paper}, the paper's loop).
     */
    record Result(ViewPicture view, RenderResult render, Accelerator accelerator) {
    }

    /**
     * Renders {@code view} of {@code scene} with the settings' size, threads and accelerator; the
     * build and the render (the rays alone, not the legend) are timed as phases of {@code timer}
     * ({@code --stats}).
     */
    static Result render(Scene scene, View view, RenderSettings settings, PhaseTimer timer) {
        Accelerator accelerator = settings.paper() ? null
                : Accelerator.of(scene, settings.accel(), settings.width(), settings.height(), 1, settings.threads());
        timer.endPhase("build");
        Supplier<Tracer> tracers = accelerator == null ? () -> new LinearTracer(scene) : accelerator.tracers();
        ViewShader shader = new ViewShader(view, scene.objects());
        RenderResult raw = ParallelRenderer.render(scene.camera(), tracers, tracer -> shader, settings.width(),
                settings.height(), 1, settings.threads(), new RenderProgress());
        timer.endPhase("render"); // drawing the view's legend belongs to making the picture: the write
        return new Result(ViewPicture.of(view, raw.image(), scene), raw, accelerator);
    }

    /** Writes the view to {@code target} in {@code format}; the scale goes to {@code err}. */
    static void write(Result result, OutputTarget target, ImageFormat format, PrintWriter err) throws IOException {
        if (target.kind() == OutputTarget.Kind.STREAM) {
            SceneIO.writeImageInto(result.view().picture(), format, target.file(), done -> { });
        } else {
            SceneIO.writeImage(result.view().picture(), format, target.file(), done -> { });
        }
        err.print("rtd: " + result.view().report().replace("\n", "\n     ").stripTrailing() + "\n");
    }

    /** Without {@code -o}: the scene's name with the view's, {@code scene.txt} → {@code scene-cost.png}. */
    static Path defaultOutput(Path scene, View view) {
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = dot > 0 ? name.substring(0, dot) : name;
        return scene.resolveSibling(base + "-" + view + ".png");
    }
}
