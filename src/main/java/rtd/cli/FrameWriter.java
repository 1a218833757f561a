package rtd.cli;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import rtd.image.Picture;
import rtd.io.AnimatedGif;
import rtd.io.ImageFormat;

/**
 * Writes frames while the next are drawn: numbered pictures on two threads, each a frame behind the drawing, or
 * one animated GIF, whose frames go in order, on one ({@link FrameRun}). A failed write is thrown at the next
 * frame handed over, or at {@link #finish}; closing stops the writers and lets an unfinished GIF's file go.
 */
final class FrameWriter implements AutoCloseable {

    private final int writers;
    private final ExecutorService threads;
    private final OutputTarget gifTarget;
    private final List<OutputTarget> targets;
    private final ImageFormat format;
    private final FramePlan plan;
    private final StandardStreams streams;
    private final ArrayDeque<Future<Void>> pending = new ArrayDeque<>();
    private AnimatedGif gif;
    private final AtomicInteger written = new AtomicInteger();

    FrameWriter(OutputTarget gifTarget, List<OutputTarget> targets, ImageFormat format, FramePlan plan,
            StandardStreams streams) {
        this.gifTarget = gifTarget;
        this.targets = targets;
        this.format = format;
        this.plan = plan;
        this.streams = streams;
        this.writers = gifTarget != null ? 1 : 2;
        this.threads = Executors.newFixedThreadPool(writers, runnable -> {
            Thread t = new Thread(runnable, "rtd-frame-writer");
            t.setDaemon(true);
            return t;
        });
    }

    /** Writes frame {@code i}, once fewer frames than there are writers wait to be written. */
    void write(int i, Picture picture) throws FileError {
        while (pending.size() >= writers) {
            waitFor(pending.removeFirst());
        }
        pending.addLast(threads.submit(() -> {
            if (gifTarget != null) {
                if (gif == null) {
                    gif = gifTarget.kind() == OutputTarget.Kind.STREAM
                            ? AnimatedGif.into(gifTarget.file(), plan.delayHundredths())
                            : AnimatedGif.replacing(gifTarget.file(), plan.delayHundredths());
                }
                gif.add(picture);
            } else {
                targets.get(i - plan.first()).write(picture, format, streams.out(), f -> { });
            }
            written.incrementAndGet();
            return null;
        }));
    }

    /** Waits for the last frame, and ends the GIF. */
    void finish() throws FileError {
        while (!pending.isEmpty()) {
            waitFor(pending.removeFirst());
        }
        if (gif != null) {
            try {
                gif.finish();
            } catch (IOException e) {
                throw new FileError("cannot write '" + gifTarget.spelt() + "'", e);
            }
        }
    }

    /** What was written: "60 frames, orbit-000.png to orbit-059.png", "orbit.gif (60 frames, 24 per second)". */
    String describe() {
        if (gifTarget != null) {
            return gifTarget.spelt() + " (" + written.get() + " frames, a delay of " + plan.delayHundredths()
                    + " hundredths of a second each)";
        }
        return written.get() + " frames, " + targets.get(0).spelt() + " to " + targets.get(targets.size() - 1).spelt();
    }

    private void waitFor(Future<Void> frame) throws FileError {
        try {
            frame.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new FileError("interrupted while writing the frames");
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof FileError fileError) {
                throw fileError;
            }
            if (cause instanceof IOException io) {
                throw new FileError("cannot write '" + gifTarget.spelt() + "'", io);
            }
            throw cause instanceof RuntimeException runtime ? runtime : new IllegalStateException(cause);
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
