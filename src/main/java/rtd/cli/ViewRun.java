package rtd.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.function.Supplier;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
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
 * {@code --view KIND}: what the camera's rays did ({@link View}), rendered on the path the picture would take (the
 * paper's loop or what {@code --accel} chose, all threads), written as a picture is, with its scale on standard error.
 */
final class ViewRun {

    private ViewRun() {
    }

    /** Where the view goes: {@code -o}, or beside the scene as {@code scene-KIND.png}; checked as a picture's is. */
    static OutputTarget plan(View view, RenderOptions options, CommandLine commandLine) throws FileError {
        Path byDefault = JobPlanner.defaultOutput(options.scene(), "-" + view);
        if (OutputTarget.DASH.equals(options.output())) {
            throw new ParameterException(commandLine, "--view writes its picture to a file; -o - (standard output) "
                    + "is for the rendered picture only: give a file name, such as " + byDefault.getFileName());
        }
        OutputTarget target = OutputTarget.of(options.output() != null ? options.output() : byDefault, options.scene(),
                "-o", commandLine);
        JobPlanner.format(target, commandLine); // a format no writer knows: a misuse, before the scene is read
        return target;
    }

    /** Renders and writes {@code view} of {@code scene} to {@code target}; its exit code, 0 or 1. */
    static int run(Scene scene, View view, OutputTarget target, RenderOptions options, StatsReport stats,
            PrintWriter err, CommandLine commandLine) {
        if (options.samples() > 1) {
            err.println("rtd: note: a view takes one ray per pixel; --samples is not used");
        }
        Accelerator accelerator = options.paper() ? null
                : Accelerator.of(scene, options.accel(), options.width(), options.height(), 1, options.threads());
        stats.endPhase("build");
        Supplier<Tracer> tracers = accelerator == null ? () -> new LinearTracer(scene) : accelerator.tracers();
        ViewShader shader = new ViewShader(view, scene.objects());
        RenderResult raw = ParallelRenderer.render(scene.camera(), tracers, tracer -> shader, options.width(),
                options.height(), 1, options.threads(), new RenderProgress());
        stats.endPhase("render"); // drawing the view's legend belongs to making the picture: the write
        ViewPicture picture = ViewPicture.of(view, raw.image(), scene);
        try {
            target.write(picture.picture(), JobPlanner.format(target, commandLine), null, done -> { });
        } catch (FileError e) {
            err.println("rtd: " + e.getMessage());
            return 1;
        }
        err.print("rtd: " + picture.report().replace("\n", "\n     ").stripTrailing() + "\n");
        stats.endPhase("write");
        if (options.stats()) { // a view runs on every thread, also the paper's loop
            err.print(stats.format(scene, accelerator, raw.work(), options.threads(), target.spelt()));
            err.flush();
        }
        return 0;
    }
}
