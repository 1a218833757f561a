package rtd.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine;
import rtd.cli.MotionOptions.FramePlan;
import rtd.image.Picture;
import rtd.io.AnimatedGif;
import rtd.io.ClockText;
import rtd.io.SceneError;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.scene.Scene;

/**
 * {@code --frames N}: the frames of an animation in one run (Part III, "Frames on the command line"). The
 * scene file is read once and parsed at each frame's clock, its meshes read once; a scene that never uses the
 * clock is drawn once and written N times. A small file is first parsed at every clock, so that a value that
 * breaks a rule at some frame (a radius below 0 at clock = 0.75) stops the run before any drawing. While a
 * frame is written the next is drawn: numbered pictures on two threads, each a frame behind the drawing, or one
 * animated GIF, whose frames go in order, on one; a failed write is thrown at the next frame handed over. Each
 * picture is written all or nothing; a GIF as a whole.
 */
final class FrameRun {

    /** Files up to this size are parsed at every clock before the first frame is drawn. */
    private static final int CHECKED_AHEAD = 1 << 20;

    private final RenderOptions options;
    private final StandardStreams streams;
    private final PrintWriter err;
    private final FramePlan plan;
    private final ArrayDeque<Future<?>> pending = new ArrayDeque<>();
    private AnimatedGif gif;

    FrameRun(RenderOptions options, StandardStreams streams, PrintWriter err, FramePlan plan) {
        this.options = options;
        this.streams = streams;
        this.err = err;
        this.plan = plan;
    }

    /** Draws the plan's frames of the job's scene (numbered pictures, or one GIF); the POV-Ray twin to {@code export}. */
    void run(JobPlanner.Job job, CompletableFuture<Void> writerReady, OutputTarget export, CommandLine commandLine)
            throws SceneException, FileError {
        boolean isGif = job.format().extension().equals("gif");
        if (options.stats()) {
            err.println("rtd: note: --stats times the phases of one picture; with --frames it is not used");
        }
        List<OutputTarget> targets = isGif ? List.of(job.target()) : frameTargets(job, commandLine);
        SceneFile file = job.source().readFile(streams);
        ExecutorService writers = Executors.newFixedThreadPool(isGif ? 1 : 2, runnable -> {
            Thread thread = new Thread(runnable, "rtd-frame-writer");
            thread.setDaemon(true);
            return thread;
        });
        try (ProgressDisplay display = ProgressDisplay.start(options.progress(), err)) {
            display.show(ProgressDisplay.Phase.of("reading " + job.source().name()));
            List<SceneError> warnings = new ArrayList<>();
            Scene first = frame(file, plan.first(), warnings);
            warnings.forEach(warning -> display.message(warning.formatAsWarning().stripTrailing()));
            if (file.usesClock() && file.size() <= CHECKED_AHEAD) { // a mistake at any frame stops the run now
                for (int i = plan.first() + 1; i <= plan.last(); i++) {
                    frame(file, i, null);
                }
            }
            if (export != null) {
                display.show(ProgressDisplay.Phase.of("writing " + export.spelt()));
                display.message(PovExport.frames(file, plan, options, export));
            }
            SceneRun.warn(first, job.source(), options, display);
            writerReady.exceptionally(failure -> null).join();
            SceneRun renderer = new SceneRun(options, streams, err);
            Picture picture = null;
            for (int i = plan.first(); i <= plan.last(); i++) {
                int done = i - plan.first();
                display.show(ProgressDisplay.Phase.counted(String.format("frame %d (%d to %d), clock %s", i,
                        plan.first(), plan.last(), ClockText.format(plan.clock(i))), () -> done / (double) plan.count()));
                if (picture == null || file.usesClock()) {
                    picture = renderer.draw(i == plan.first() ? first : frame(file, i, null));
                }
                Picture drawn = picture;
                OutputTarget target = targets.get(isGif ? 0 : done);
                waitUntilPending(isGif ? 0 : 1);
                pending.addLast(writers.submit(() -> write(drawn, target, job, isGif)));
            }
            waitUntilPending(0);
            if (gif != null) {
                finishGif(targets.get(0));
            }
        } finally {
            stop(writers);
        }
        err.print("rtd: wrote " + (isGif ? targets.get(0).spelt() + " (" + plan.count() + " frames, a delay of "
                + plan.delayHundredths() + " hundredths of a second each)" : targets.size() == 1 ? "1 frame, "
                + targets.get(0).spelt() : targets.size() + " frames, " + targets.get(0).spelt() + " to "
                + targets.get(targets.size() - 1).spelt()) + "\n");
    }

    /** The scene at frame {@code i}'s clock, at the size asked; a mistake names the clock if its message does not. */
    private Scene frame(SceneFile file, int i, List<SceneError> warnings) throws SceneException {
        double clock = plan.clock(i);
        try {
            return options.scale().of(file.at(clock, warnings));
        } catch (SceneException e) {
            throw new SceneException(e.errors().stream().map(error -> error.message().contains("clock =") ? error
                    : new SceneError(error.file(), error.line(), error.column(), error.message() + " (frame " + i
                            + ", at clock = " + ClockText.format(clock) + ")", error.sourceLine(), error.help()))
                    .toList(), false);
        }
    }

    /** Each numbered picture's target, all checked before anything is drawn. */
    private List<OutputTarget> frameTargets(JobPlanner.Job job, CommandLine commandLine) throws FileError {
        if (job.target().kind() == OutputTarget.Kind.STREAM) {
            return Collections.nCopies(plan.count(), job.target());
        }
        List<OutputTarget> targets = new ArrayList<>();
        for (int i = plan.first(); i <= plan.last(); i++) {
            targets.add(OutputTarget.of(plan.frameFile(job.target().spelt(), i), job.source().stdin()
                    ? streams.inPath().orElse(job.source().path()) : job.source().path(), "-o", commandLine));
        }
        return targets;
    }

    /** Writes one frame, on a writer's thread: a numbered picture, or the GIF's next frame. */
    private Void write(Picture picture, OutputTarget target, JobPlanner.Job job, boolean isGif) throws FileError {
        if (!isGif) {
            target.write(picture, job.format(), streams.out(), f -> { });
            return null;
        }
        try { // the GIF's file is opened at the first frame (a FIFO waits for its reader there)
            if (gif == null) {
                gif = target.kind() == OutputTarget.Kind.STREAM ? AnimatedGif.into(target.file(), plan.delayHundredths())
                        : AnimatedGif.replacing(target.file(), plan.delayHundredths());
            }
            gif.add(picture);
            return null;
        } catch (IOException e) {
            throw new FileError("cannot write '" + target.spelt() + "'", e);
        }
    }

    private void finishGif(OutputTarget target) throws FileError {
        try {
            gif.finish();
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
                throw e.getCause() instanceof RuntimeException runtime ? runtime : new IllegalStateException(e.getCause());
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
