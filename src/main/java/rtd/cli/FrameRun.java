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
import rtd.image.Picture;
import rtd.io.AnimatedGif;
import rtd.io.ClockedScene;
import rtd.io.ImageFormat;
import rtd.io.SceneError;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.scene.Scene;

/**
 * {@code --frames N}: the frames of an animation in one run (Part III, "Frames on the command line"). The
 * scene file is read once and parsed at each frame's clock, its meshes read once; a scene that never uses the
 * clock is drawn once and written N times. A small file is first parsed at every clock, so that a value that
 * breaks a rule at some frame (a radius below 0 at clock = 0.75) stops the run before any drawing. While a
 * frame is written the next is drawn. Each picture is written all or nothing; a GIF as a whole.
 */
record FrameRun(RenderOptions options, StandardStreams streams, PrintWriter err, CommandLine commandLine,
        FramePlan plan) {

    /** Files up to this size are parsed at every clock before the first frame is drawn. */
    private static final int CHECKED_AHEAD = 1 << 20;

    /** Draws the plan's frames of {@code source} to {@code target} (numbered, or one GIF); the POV-Ray twin to {@code export}. */
    void run(SceneSource source, OutputTarget target, ImageFormat format, CompletableFuture<Void> writerReady,
            OutputTarget export) throws SceneException, FileError {
        boolean gif = format.extension().equals("gif");
        if (options.stats()) {
            err.println("rtd: note: --stats times the phases of one picture; with --frames it is not used");
        }
        List<OutputTarget> targets = gif ? List.of(target) : frameTargets(source, target);
        SceneFile file = source.readFile(streams);
        String summary;
        try (ProgressDisplay display = ProgressDisplay.start(options.progress(), err);
                Writer writer = new Writer(gif ? target : null, targets, format)) {
            display.show(ProgressDisplay.Phase.of("reading " + source.name()));
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
            SceneRun.warn(first, source, options, display);
            writerReady.exceptionally(failure -> null).join();
            SceneRun renderer = new SceneRun(options, streams, err);
            Picture picture = null;
            for (int i = plan.first(); i <= plan.last(); i++) {
                int done = i - plan.first();
                display.show(ProgressDisplay.Phase.counted(String.format("frame %d (%d to %d), clock %s", i,
                        plan.first(), plan.last(), ClockedScene.clockText(plan.clock(i))),
                        () -> done / (double) plan.count()));
                if (picture == null || file.usesClock()) {
                    picture = renderer.draw(i == plan.first() ? first : frame(file, i, null));
                }
                writer.write(i, picture);
            }
            writer.finish();
            summary = "rtd: wrote " + writer.describe() + "\n";
        }
        err.print(summary);
    }

    /** The scene at frame {@code i}'s clock, at the size asked; a mistake names the clock if its message does not. */
    private Scene frame(SceneFile file, int i, List<SceneError> warnings) throws SceneException {
        double clock = plan.clock(i);
        try {
            return options.scale().of(file.at(clock, warnings));
        } catch (SceneException e) {
            throw new SceneException(e.errors().stream().map(error -> error.message().contains("clock =") ? error
                    : new SceneError(error.file(), error.line(), error.column(), error.message() + " (frame " + i
                            + ", at clock = " + ClockedScene.clockText(clock) + ")", error.sourceLine(), error.help()))
                    .toList(), false);
        }
    }

    /** Each numbered picture's target, all checked before anything is drawn. */
    private List<OutputTarget> frameTargets(SceneSource source, OutputTarget target) throws FileError {
        if (target.kind() == OutputTarget.Kind.STREAM) {
            return Collections.nCopies(plan.count(), target);
        }
        OutputTarget[] targets = new OutputTarget[plan.count()];
        for (int i = 0; i < targets.length; i++) {
            targets[i] = OutputTarget.of(plan.frameFile(target.spelt(), plan.first() + i),
                    source.stdin() ? streams.inPath().orElse(source.path()) : source.path(), "-o", commandLine);
        }
        return List.of(targets);
    }

    /**
     * Writes frames while the next are drawn: numbered pictures on two threads, each a frame behind the drawing, or
     * one animated GIF, whose frames go in order, on one. A failed write is thrown at the next frame handed over,
     * or at {@link #finish}; closing stops the writers and lets an unfinished GIF's file go.
     */
    private final class Writer implements AutoCloseable {

        private final OutputTarget gifTarget;
        private final List<OutputTarget> targets;
        private final ImageFormat format;
        private final int writers;
        private final ExecutorService threads;
        private final ArrayDeque<Future<?>> pending = new ArrayDeque<>();
        private AnimatedGif gif;

        Writer(OutputTarget gifTarget, List<OutputTarget> targets, ImageFormat format) {
            this.gifTarget = gifTarget;
            this.targets = targets;
            this.format = format;
            this.writers = gifTarget != null ? 1 : 2;
            this.threads = Executors.newFixedThreadPool(writers, runnable -> {
                Thread thread = new Thread(runnable, "rtd-frame-writer");
                thread.setDaemon(true);
                return thread;
            });
        }

        /** Writes frame {@code i}, once fewer frames than there are writers wait to be written. */
        void write(int i, Picture picture) throws FileError {
            waitUntilPending(writers - 1);
            pending.addLast(threads.submit(() -> {
                if (gifTarget == null) {
                    targets.get(i - plan.first()).write(picture, format, streams.out(), f -> { });
                    return null;
                }
                try { // the GIF's file is opened at the first frame (a FIFO waits for its reader there)
                    if (gif == null) {
                        gif = gifTarget.kind() == OutputTarget.Kind.STREAM
                                ? AnimatedGif.into(gifTarget.file(), plan.delayHundredths())
                                : AnimatedGif.replacing(gifTarget.file(), plan.delayHundredths());
                    }
                    gif.add(picture);
                    return null;
                } catch (IOException e) {
                    throw new FileError("cannot write '" + gifTarget.spelt() + "'", e);
                }
            }));
        }

        /** Waits for the last frame, and ends the GIF. */
        void finish() throws FileError {
            waitUntilPending(0);
            try {
                if (gif != null) {
                    gif.finish();
                }
            } catch (IOException e) {
                throw new FileError("cannot write '" + gifTarget.spelt() + "'", e);
            }
        }

        /**
         * What was written, once every frame was: "60 frames, orbit-000.png to orbit-059.png", "1 frame,
         * orbit-003.png".
         */
        String describe() {
            if (gifTarget != null) {
                return gifTarget.spelt() + " (" + plan.count() + " frames, a delay of " + plan.delayHundredths()
                        + " hundredths of a second each)";
            }
            return targets.size() == 1 ? "1 frame, " + targets.get(0).spelt()
                    : targets.size() + " frames, " + targets.get(0).spelt() + " to "
                            + targets.get(targets.size() - 1).spelt();
        }

        /** Waits, oldest first, until at most {@code most} frames wait to be written. */
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

        @Override
        public void close() {
            threads.shutdownNow();
            try {
                threads.awaitTermination(1, TimeUnit.MINUTES); // the GIF is closed once no frame is being added
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
}
