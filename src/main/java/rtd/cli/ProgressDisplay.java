package rtd.cli;

import java.io.PrintWriter;
import java.util.Locale;
import rtd.render.RenderProgress;

/**
 * A one-line progress display on standard error: percent done, rate and time left, redrawn
 * in place a few times a second. It shows only on renders that take more than about a second.
 */
final class ProgressDisplay implements AutoCloseable {

    private static final long DELAY_MILLIS = 1000;
    private static final long PERIOD_MILLIS = 250;

    private final PrintWriter err;
    private final RenderProgress progress;
    private final int rows;
    private final long pixelsPerRow;
    private final long start = System.nanoTime();
    private final Thread thread;
    private volatile boolean done;
    private boolean shown;

    private ProgressDisplay(PrintWriter err, RenderProgress progress, int rows, int pixelsPerRow) {
        this.err = err;
        this.progress = progress;
        this.rows = rows;
        this.pixelsPerRow = pixelsPerRow;
        this.thread = new Thread(this::run, "rtd-progress");
        thread.setDaemon(true);
    }

    /**
     * Starts a display for a render of {@code width × height}; if not {@code enabled}, one that
     * never shows anything.
     */
    static ProgressDisplay start(boolean enabled, PrintWriter err, RenderProgress progress, int width, int height) {
        ProgressDisplay display = new ProgressDisplay(err, progress, height, width);
        if (enabled) {
            display.thread.start();
        }
        return display;
    }

    private void run() {
        try {
            Thread.sleep(DELAY_MILLIS);
            while (!done) {
                draw();
                Thread.sleep(PERIOD_MILLIS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private synchronized void draw() {
        if (done) {
            return;
        }
        int finished = progress.rowsDone();
        double seconds = (System.nanoTime() - start) / 1e9;
        double megaRays = finished * pixelsPerRow / 1e6;
        double left = finished == 0 ? Double.NaN : seconds * (rows - finished) / finished;
        err.print(String.format(Locale.ROOT, "\rrendering %3d%%  %6.2f Mrays/s  %s left ",
                100L * finished / rows, megaRays / seconds, Double.isNaN(left) ? "?" : Math.round(left) + " s"));
        err.flush();
        shown = true;
    }

    /** Stops the display and clears its line. */
    @Override
    public synchronized void close() {
        done = true;
        thread.interrupt();
        if (shown) {
            err.print("\r\033[K");
            err.flush();
        }
    }
}
