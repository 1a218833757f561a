package rtd.cli;

import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.DoubleConsumer;
import java.util.function.Function;
import java.util.function.Supplier;
import picocli.CommandLine;
import rtd.image.Picture;
import rtd.io.ImageFormat;
import rtd.io.ImageWriting;
import rtd.io.SceneError;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.image.Rgb;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.render.Shader;
import rtd.render.Tracer;
import rtd.render.WorkCount;
import rtd.scene.Scene;
import rtd.shade.FlatShader;
import rtd.shade.WhittedShader;

/**
 * One scene from file to picture: read, write the {@code --export-pov} file if one is asked for,
 * build what {@code --accel} chose (the BVH, the view grid, the light grids), render, warn if
 * nothing is in view, write;
 * timed per phase for {@code --stats}, and shown on the progress line.
 */
final class SceneRun {

    private final Settings settings;
    private final CommandLine commandLine;
    private final StandardStreams streams;
    private final PrintWriter err;

    SceneRun(Settings settings, CommandLine commandLine, StandardStreams streams) {
        this.settings = settings;
        this.commandLine = commandLine;
        this.streams = streams;
        this.err = commandLine.getErr();
    }

    /**
     * Renders {@code source} to {@code target} in {@code format}, once {@code writerReady} (the
     * warm-up of {@code javax.imageio}, which runs meanwhile) is done; with the scene written for
     * POV-Ray to {@code export} (or null) before it is rendered.
     */
    void run(SceneSource source, OutputTarget target, ImageFormat format, CompletableFuture<Void> writerReady,
            OutputTarget export) throws SceneException, FileError {
        String report;
        try (ProgressDisplay display = ProgressDisplay.start(settings.progress(), err)) {
            PhaseTimer timer = new PhaseTimer();
            display.show(ProgressDisplay.Phase.of("reading " + source.name()));
            Scene scene = settings.scale().of(read(source, display));
            timer.endPhase("parse");
            if (export != null) { // --export-pov, planned with the picture's file, from this one read of the scene
                display.show(ProgressDisplay.Phase.of("writing " + export.spelt()));
                display.message(PovExportRun.write(scene, export, settings.width(), settings.height()));
                timer.endPhase("export");
            }

            Accelerator.Kind kind = settings.paper() ? Accelerator.Kind.LOOP : Accelerator.choose(scene, settings.accel());
            display.show(ProgressDisplay.Phase.of(kind.building));
            Accelerator accelerator = settings.paper() ? null : Accelerator.build(kind, scene, settings.width(),
                    settings.height(), settings.samples(), settings.threads());
            timer.endPhase("build");

            Optional<String> cameraInPlane = CameraInPlane.warning(source.name(), scene, settings.width(), settings.height());
            if (cameraInPlane.isPresent()) {
                display.message(cameraInPlane.get());
            }
            if (!settings.paper()) { // --paper draws no light, and says so
                for (String note : LightNotes.of(source.name(), scene)) {
                    display.message(note);
                }
            }
            RenderProgress progress = new RenderProgress();
            display.show(ProgressDisplay.Phase.rendering(() -> progress.rowsDone() / (double) settings.height(),
                    (double) settings.width() * settings.height() / 1e6));
            RenderResult result = settings.paper() ? renderAsThePaper(scene) : renderInParallel(scene, accelerator, progress);
            timer.endPhase("render");
            if (!hitSomething(scene, accelerator, result.image())) {
                display.message(NothingInView.warning(source.name(), scene, settings.width(), settings.height()));
            }

            AtomicLong written = new AtomicLong(Double.doubleToLongBits(0));
            display.show(ProgressDisplay.Phase.counted("writing " + target.spelt(),
                    () -> Double.longBitsToDouble(written.get())));
            writerReady.exceptionally(failure -> null).join(); // a failed warm-up: the write says why
            write(result.image(), target, format, fraction -> written.set(Double.doubleToLongBits(fraction)));
            timer.endPhase("write");
            report = settings.stats()
                    ? StatsReport.format(timer, scene, accelerator, result.work(),
                            settings.paper() ? 1 : settings.threads(), target.spelt()) : "";
        }
        err.print(report); // once the progress line is gone
    }

    /** Reads the scene; its warnings are shown as they come, each located as a mistake is. */
    private Scene read(SceneSource source, ProgressDisplay display) throws SceneException, FileError {
        try {
            List<SceneError> warnings = new ArrayList<>();
            Scene scene = source.read(streams, warnings);
            for (SceneError warning : warnings) {
                display.message(warning.formatAsWarning().stripTrailing());
            }
            return scene;
        } catch (IOException e) {
            throw new FileError("cannot read the scene file '" + source.name() + "': " + FileProblems.reason(e), e);
        }
    }

    /** The tracers for the BVH, the view grid, or the paper's loop; for {@code --paper}, the paper's loop. */
    private static Supplier<Tracer> tracers(Scene scene, Accelerator accelerator) {
        return accelerator != null ? accelerator.tracers() : () -> new LinearTracer(scene);
    }

    /**
     * All cores, with the tracers {@code --accel} chose ({@link Accelerator}); in flat
     * colours, or shaded ({@link WhittedShader}) if the scene has lights.
     */
    private RenderResult renderInParallel(Scene scene, Accelerator accelerator, RenderProgress progress) {
        FlatShader flat = new FlatShader(scene);
        Function<Tracer, Shader> shaders = scene.lights().isEmpty()
                ? tracer -> flat
                : tracer -> new WhittedShader(scene, tracer);
        return ParallelRenderer.render(scene.camera(), accelerator.tracers(), shaders, settings.width(),
                settings.height(), settings.samples(), settings.threads(), progress);
    }

    /**
     * {@code --paper}: the paper's {@link Scene#render} itself, one ray per pixel on this
     * thread, in the paper's flat colours.
     */
    private RenderResult renderAsThePaper(Scene scene) {
        if (!scene.lights().isEmpty() || settings.samples() > 1) {
            err.println("rtd: note: --paper draws as the paper does, one ray per pixel in flat colours: "
                    + "the scene's lights and --samples are not used");
        }
        int width = settings.width();
        int height = settings.height();
        BufferedImage image = scene.render(width, height);
        int[] rgb = image.getRGB(0, 0, width, height, null, 0, width);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF; // getRGB adds an opaque alpha channel
        }
        return new RenderResult(new Picture(width, height, rgb), WorkCount.testsOf(scene.objects(), (long) width * height));
    }

    /**
     * Whether some ray hit an object. A pixel that is not background says so at once; a picture
     * of background alone says so only if no object has the background's colour, and otherwise
     * the rays are traced again with a shader that marks hits (rare: such an object alone in view).
     */
    private boolean hitSomething(Scene scene, Accelerator accelerator, Picture picture) {
        int background = scene.ambient().getRGB();
        if (NothingInView.showsSomething(picture, background)) {
            return true;
        }
        if (!NothingInView.someObjectLooksLikeBackground(scene)) {
            return false;
        }
        Shader hitMarks = (rays, hits, i) -> hits.index(i) < 0 ? Rgb.BLACK : new Rgb(1, 1, 1);
        Picture marks = ParallelRenderer.render(scene.camera(), tracers(scene, accelerator), tracer -> hitMarks,
                settings.width(), settings.height(), settings.threads(), new RenderProgress()).image();
        return NothingInView.showsSomething(marks, 0);
    }

    private void write(Picture picture, OutputTarget target, ImageFormat format,
            DoubleConsumer progress) throws FileError {
        try {
            switch (target.kind()) {
                case STREAM -> SceneIO.writeImageInto(picture, format, target.file(), progress);
                case REPLACE -> SceneIO.writeImage(picture, format, target.file(), progress);
                case STANDARD_OUTPUT -> ImageWriting.write(picture, format, new BufferedOutputStream(streams.out(), 1 << 16),
                        progress);
            }
        } catch (IOException e) {
            throw new FileError("cannot write '" + target.spelt() + "': " + FileProblems.reason(e), e);
        }
    }
}
