package rtd.cli;

import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;
import java.util.function.Supplier;
import rtd.cli.Accelerator.StructureCache;
import rtd.image.Picture;
import rtd.io.SceneError;
import rtd.io.SceneException;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.render.Shader;
import rtd.render.Tracer;
import rtd.render.WorkCount;
import rtd.scene.Scene;
import rtd.scene.SceneWarnings;
import rtd.shade.FlatShader;
import rtd.shade.WhittedShader;

/**
 * One scene from file to picture: read, write the {@code --export-pov} file if asked, build what {@code --accel}
 * chose, warn of a scene that looks wrong, render, warn if nothing is in view, write; each phase timed for
 * {@code --stats} and shown on the progress line. The picture replaces its file only once it is complete.
 * {@code kept} holds what one frame built that the next may use again.
 */
record SceneRun(RenderOptions options, StandardStreams streams, PrintWriter err, StructureCache kept) {

    SceneRun(RenderOptions options, StandardStreams streams, PrintWriter err) {
        this(options, streams, err, new StructureCache());
    }

    /** Renders the job's scene once {@code writerReady}; the POV-Ray twin to {@code export}. */
    void run(JobPlanner.Job job, CompletableFuture<Void> writerReady, OutputTarget export)
            throws SceneException, FileError {
        SceneSource source = job.source();
        OutputTarget target = job.target();
        String report;
        try (ProgressDisplay display = ProgressDisplay.start(options.progress(), err)) {
            StatsReport stats = new StatsReport();
            Scene scene = read(source, streams, options, export, display, stats);

            Accelerator.Kind kind = Accelerator.choose(scene, options.engine());
            display.show(ProgressDisplay.Phase.of(kind.building));
            Accelerator accelerator = Accelerator.build(kind, scene, options.width(), options.height(),
                    options.samples(), options.threads(), kept);
            stats.endPhase("build");

            warn(scene, source, options, display);
            RenderResult result = render(scene, accelerator, display);
            stats.endPhase("render");
            if (!NothingInView.hitSomething(scene, accelerator.tracers(), result.image(), options.threads())) {
                display.message(NothingInView.warning(source.name(), scene, options));
            }

            AtomicLong written = new AtomicLong(Double.doubleToLongBits(0));
            display.show(ProgressDisplay.Phase.counted("writing " + target.spelt(),
                    () -> Double.longBitsToDouble(written.get())));
            writerReady.exceptionally(failure -> null).join(); // a failed warm-up: the write says why
            target.write(result.image(), job.format(), streams.out(), f -> written.set(Double.doubleToLongBits(f)));
            stats.endPhase("write");
            report = options.stats() ? stats.format(scene, accelerator, result.work(),
                    options.paper() ? 1 : options.threads(), target.spelt()) : "";
        }
        err.print(report); // once the progress line is gone
    }

    /** Warns of what in {@code scene} looks wrong ({@link SceneWarnings}); with {@code --paper}, not of lights. */
    static void warn(Scene scene, SceneSource source, RenderOptions options, ProgressDisplay display) {
        SceneWarnings.of(scene, options.width(), options.height(), !options.paper())
                .forEach(warning -> display.message("rtd: warning: " + source.name() + ": " + warning));
    }

    /** Reads {@code source}, its warnings on {@code display}, and writes its POV-Ray twin to {@code export}. */
    static Scene read(SceneSource source, StandardStreams streams, RenderOptions options, OutputTarget export,
            ProgressDisplay display, StatsReport stats) throws SceneException, FileError {
        display.show(ProgressDisplay.Phase.of("reading " + source.name()));
        List<SceneError> warnings = new ArrayList<>();
        Scene scene = options.scale().of(source.read(streams, options.clock(), warnings));
        warnings.forEach(warning -> display.message(warning.formatAsWarning().stripTrailing()));
        stats.endPhase("parse");
        if (export != null) {
            display.show(ProgressDisplay.Phase.of("writing " + export.spelt()));
            display.message(PovExport.still(scene, export, options.width(), options.height()));
            stats.endPhase("export");
        }
        return scene;
    }

    /**
     * On all cores with the tracers {@code --accel} chose, in flat colours or shaded ({@link WhittedShader}) if
     * the scene has lights; for {@code --paper}, the paper's own {@link Scene#render}, one ray a pixel on this
     * thread, in flat colours. The progress line counts the rays as the tracers do, which {@code --stats} sums.
     */
    RenderResult render(Scene scene, Accelerator accelerator, ProgressDisplay display) {
        int width = options.width();
        int height = options.height();
        if (options.paper()) {
            if (!scene.lights().isEmpty() || options.samples() > 1) {
                err.println("rtd: note: --paper draws as the paper does, one ray per pixel in flat colours: "
                        + "the scene's lights and --samples are not used");
            }
            display.show(ProgressDisplay.Phase.of("rendering"));
            BufferedImage image = scene.render(width, height);
            int[] rgb = image.getRGB(0, 0, width, height, null, 0, width);
            Arrays.setAll(rgb, i -> rgb[i] & 0xFFFFFF); // getRGB adds an opaque alpha channel
            return new RenderResult(new Picture(width, height, rgb), WorkCount.testsOf(scene.objects(),
                    (long) width * height));
        }
        FlatShader flat = new FlatShader(scene);
        Function<Tracer, Shader> shaders = scene.lights().isEmpty() ? tracer -> flat
                : tracer -> new WhittedShader(scene, tracer);
        List<Tracer> tracers = new CopyOnWriteArrayList<>();
        RenderProgress progress = new RenderProgress();
        display.show(new ProgressDisplay.Phase("rendering", () -> progress.rowsDone() / (double) height,
                () -> rays(tracers)));
        Supplier<Tracer> counted = () -> {
            Tracer tracer = accelerator.tracers().get();
            tracers.add(tracer);
            return tracer;
        };
        return ParallelRenderer.render(scene.camera(), counted, shaders, width, height, options.samples(),
                options.threads(), progress);
    }

    /** The rays {@code tracers} have traced so far, read while they trace: a count for the eye, not for --stats. */
    private static long rays(List<Tracer> tracers) {
        try {
            return tracers.stream().mapToLong(tracer -> tracer.work().rays()).sum();
        } catch (RuntimeException e) {
            return -1; // a tracer that cannot tell while it works: no rate, rather than a wrong one
        }
    }

    /** One frame of an animation, quietly, with what the last frame built if it still serves ({@link #kept}). */
    Picture draw(Scene scene) {
        Accelerator accelerator = Accelerator.build(Accelerator.choose(scene, options.engine()), scene, options.width(),
                options.height(), options.samples(), options.threads(), kept);
        return render(scene, accelerator, ProgressDisplay.start(false, err)).image();
    }
}
