package rtd.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.DoubleAccumulator;
import java.util.function.Function;
import java.util.function.Supplier;
import rtd.accel.Accelerator;
import rtd.accel.Accelerator.StructureCache;
import rtd.image.Picture;
import rtd.io.AnimatedGif;
import rtd.io.ImageFormat;
import rtd.io.SceneError;
import rtd.io.SceneException;
import rtd.io.SceneFile;
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
 * One scene from file to picture: read, export to POV-Ray if asked, build what {@code --accel} chose, warn, render,
 * write; each phase timed for {@code --stats} and shown on the progress line. With {@code --frames N} (Part III,
 * "Frames on the command line") the file is read once and parsed at each frame's clock, a small file at every clock
 * first, so that a rule broken at some frame stops the run before any drawing; what one frame built that the next
 * may use is kept. While a frame is written the next is drawn. Each file is replaced only once complete.
 */
final class SceneRun {

    /** Files up to this size are parsed at every clock before the first frame is drawn. */
    private static final int CHECKED_AHEAD = 1 << 20;

    private final RenderOptions options;
    private final StandardStreams streams;
    private final PrintWriter err;
    private final FramePlan plan;
    private final StructureCache kept = new StructureCache();
    private final ArrayDeque<Future<?>> pending = new ArrayDeque<>();
    private AnimatedGif gif;
    /** Whether the note on what {@code --paper} leaves out was shown: once a scene, not once a frame. */
    private boolean paperNoted;

    SceneRun(RenderOptions options, StandardStreams streams, PrintWriter err, FramePlan plan) {
        this.options = options;
        this.streams = streams;
        this.err = err;
        this.plan = plan;
    }

    /** Renders the job's scene once {@code writerReady}; the POV-Ray twin to {@code export}. */
    void run(JobPlanner.Job job, CompletableFuture<Void> writerReady, OutputTarget export)
            throws SceneException, FileError {
        if (plan != null) {
            frames(job, writerReady, export);
            return;
        }
        SceneSource source = job.source();
        OutputTarget target = job.target();
        String report;
        try (ProgressDisplay display = ProgressDisplay.start(options.progress(), err)) {
            StatsReport stats = new StatsReport();
            Scene scene = read(source, streams, options, export, display, stats);

            Accelerator accelerator = build(scene, display);
            stats.endPhase("build");

            warn(scene, source, display);
            RenderResult result = render(scene, accelerator, display);
            stats.endPhase("render");
            if (!NothingInView.hitSomething(scene, accelerator.tracers(), result.image(), options.threads())) {
                display.message(NothingInView.warning(source.name(), scene, options));
            }

            DoubleAccumulator written = new DoubleAccumulator(Math::max, 0); // the fraction of the picture written
            display.show(ProgressDisplay.Phase.counted("writing " + target.spelt(), written::get));
            writerReady.exceptionally(failure -> null).join(); // a failed warm-up: the write says why
            target.write(result.image(), job.format(), streams.out(), written::accumulate);
            stats.endPhase("write");
            report = options.stats() ? stats.format(scene, accelerator, result.work(),
                    options.paper() ? 1 : options.threads(), target.spelt()) : "";
        }
        err.print(report); // once the progress line is gone
    }

    /** What {@code --accel} chose for {@code scene}, built with what the last frame built where it serves. */
    private Accelerator build(Scene scene, ProgressDisplay display) {
        Accelerator.Kind kind = Accelerator.choose(scene, options.engine(), options.width(), options.height(),
                options.samples());
        display.show(ProgressDisplay.Phase.of(kind.building()));
        return Accelerator.build(kind, scene, options.width(), options.height(), options.samples(), options.threads(),
                kept);
    }

    /** Warns of what in {@code scene} looks wrong; with {@code --paper}, not of lights. */
    private void warn(Scene scene, SceneSource source, ProgressDisplay display) {
        SceneWarnings.of(scene, options.width(), options.height(), !options.paper())
                .forEach(warning -> display.message("rtd: warning: " + source.name() + ": " + warning));
    }

    /** Reads {@code source}, its warnings on {@code display}, and writes its POV-Ray twin to {@code export}. */
    static Scene read(SceneSource source, StandardStreams streams, RenderOptions options, OutputTarget export,
            ProgressDisplay display, StatsReport stats) throws SceneException, FileError {
        display.show(ProgressDisplay.Phase.of("reading " + source.name()));
        List<SceneError> warnings = new ArrayList<>();
        SceneFile file = source.readFile(streams, options.parseThreads()); // at clock 0 parsed once: its bytes let go
        Scene scene = options.scale().of(options.clock() != 0 ? file.at(options.clock(), warnings)
                : file.once(warnings));
        warnings.forEach(warning -> display.message(warning.formatAsWarning().stripTrailing()));
        stats.endPhase("parse");
        if (export != null) {
            display.show(ProgressDisplay.Phase.of("writing " + export.spelt()));
            display.message(PovExport.still(scene, export, options.width(), options.height()));
            stats.endPhase("export");
        }
        return scene;
    }

    /** With {@code accelerator} on all cores, shaded if lit; {@code --paper}: {@link Scene#render} on this thread. */
    private RenderResult render(Scene scene, Accelerator accelerator, ProgressDisplay display) {
        int width = options.width();
        int height = options.height();
        if (options.paper()) {
            if (!paperNoted && (!scene.lights().isEmpty() || options.samples() > 1)) {
                paperNoted = true;
                err.println("rtd: note: --paper draws as the paper does, one ray per pixel in flat colours: "
                        + "the scene's lights and --samples are not used");
            }
            display.show(ProgressDisplay.Phase.of("rendering"));
            return new RenderResult(Picture.of(scene.render(width, height)), WorkCount.testsOf(scene.objects(),
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

    /** Draws the plan's frames of the job's scene (numbered pictures, one GIF); the POV-Ray twin to {@code export}. */
    private void frames(JobPlanner.Job job, CompletableFuture<Void> writerReady, OutputTarget export)
            throws SceneException, FileError {
        boolean isGif = job.format().extension().equals("gif");
        if (options.stats()) {
            err.println("rtd: note: --stats times the phases of one picture; with --frames it is not used");
        }
        List<OutputTarget> targets = isGif ? List.of(job.target()) : plan.targets(job.target(), job.source().stdin()
                ? streams.inPath().orElse(job.source().path()) : job.source().path());
        SceneFile file = job.source().readFile(streams, options.parseThreads());
        ExecutorService writers = Executors.newFixedThreadPool(isGif ? 1 : 2, runnable -> {
            Thread thread = new Thread(runnable, "rtd-frame-writer");
            thread.setDaemon(true);
            return thread;
        });
        try (ProgressDisplay display = ProgressDisplay.start(options.progress(), err)) {
            display.show(ProgressDisplay.Phase.of("reading " + job.source().name()));
            List<SceneError> warnings = new ArrayList<>();
            Scene first = plan.frame(file, options.scale(), plan.first(), warnings);
            warnings.forEach(warning -> display.message(warning.formatAsWarning().stripTrailing()));
            if (file.usesClock() && file.size() <= CHECKED_AHEAD) { // a mistake at any frame stops the run now
                for (int i = plan.first() + 1; i <= plan.last(); i++) {
                    plan.frame(file, options.scale(), i, null);
                }
            }
            if (export != null) {
                display.show(ProgressDisplay.Phase.of("writing " + export.spelt()));
                display.message(PovExport.frames(file, plan, options, export));
            }
            warn(first, job.source(), display);
            writerReady.exceptionally(failure -> null).join();
            Picture picture = null;
            for (int i = plan.first(); i <= plan.last(); i++) {
                int done = i - plan.first();
                String name = String.format("frame %d (%d to %d), clock %s", i, plan.first(), plan.last(),
                        SceneWarnings.number(plan.clock(i)));
                display.show(ProgressDisplay.Phase.counted(name, () -> done / (double) plan.count()));
                if (picture == null || file.usesClock()) { // quietly, with what the last frame built if it serves
                    Scene scene = i == plan.first() ? first : plan.frame(file, options.scale(), i, null);
                    ProgressDisplay quiet = ProgressDisplay.start(false, err);
                    picture = render(scene, build(scene, quiet), quiet).image();
                }
                Picture drawn = picture;
                OutputTarget target = targets.get(isGif ? 0 : done);
                waitUntilPending(isGif ? 0 : 1);
                pending.addLast(writers.submit(() -> write(drawn, target, job.format(), isGif)));
            }
            waitUntilPending(0);
            if (isGif) { // once every frame is in: a GIF that failed midway never replaces the file
                pending.addLast(writers.submit(() -> write(null, targets.get(0), job.format(), true)));
                waitUntilPending(0);
            }
        } finally {
            stop(writers);
        }
        err.print("rtd: wrote " + (isGif ? targets.get(0).spelt() + " (" + plan.count() + " frames, a delay of "
                + plan.delayHundredths() + " hundredths of a second each)" : targets.size() == 1 ? "1 frame, "
                + targets.get(0).spelt() : targets.size() + " frames, " + targets.get(0).spelt() + " to "
                + targets.get(targets.size() - 1).spelt()) + "\n");
    }

    /** Writes one frame, on a writer's thread: a numbered picture, or the GIF's next frame (null: its end). */
    private Void write(Picture picture, OutputTarget target, ImageFormat format, boolean isGif) throws FileError {
        if (!isGif) {
            target.write(picture, format, streams.out(), f -> { });
            return null;
        }
        try { // the GIF's file is opened at the first frame (a FIFO waits for its reader there)
            if (gif == null) {
                int delay = plan.delayHundredths();
                gif = target.kind() == OutputTarget.Kind.STREAM ? AnimatedGif.into(target.file(), delay)
                        : AnimatedGif.replacing(target.file(), delay);
            }
            if (picture == null) {
                gif.finish();
            } else {
                gif.add(picture);
            }
            return null;
        } catch (IOException e) {
            throw new FileError("cannot write '" + target.spelt() + "'", e);
        }
    }

    /** Waits, oldest first, until at most {@code most} frames wait to be written; a failed write is thrown. */
    private void waitUntilPending(int most) throws FileError {
        while (pending.size() > most) {
            try {
                pending.removeFirst().get();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new FileError("interrupted while writing the frames");
            } catch (ExecutionException e) {
                if (e.getCause() instanceof FileError error) {
                    throw error;
                }
                throw e.getCause() instanceof RuntimeException runtime ? runtime
                        : new IllegalStateException(e.getCause());
            }
        }
    }

    /** Stops the writers, then lets an unfinished GIF's file go. */
    private void stop(ExecutorService writers) {
        writers.shutdownNow();
        try {
            writers.awaitTermination(1, TimeUnit.MINUTES); // the GIF is closed once no frame is being added
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        try {
            if (gif != null) {
                gif.close();
            }
        } catch (IOException e) {
            // the run has failed already, or the GIF is in place: nothing to add
        }
    }
}
