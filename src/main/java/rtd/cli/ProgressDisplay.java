package rtd.cli;

import java.io.PrintWriter;
import java.util.function.DoubleSupplier;
import java.util.function.IntSupplier;
import java.util.function.LongSupplier;

/**
 * A one-line progress display on standard error, redrawn in place four times a second ({@link ProgressLine}):
 * what the run is doing ("reading scene.txt", "rendering", "writing out.png"), how much is done and how long it
 * has left. It shows only on a terminal, once a run has taken a second; it ends short of the last column (a full
 * line would wrap, and each {@code \r} redraw add a line); and it is cleared when the run ends, also by Ctrl-C.
 */
final class ProgressDisplay implements AutoCloseable {

    private static final long PERIOD_MILLIS = 250;
    private static final String CLEAR = "\r\033[K";

    private final PrintWriter err;
    private final IntSupplier columnsOfTerminal;
    private final long delayMillis;
    private final Thread thread;
    private final Thread clearOnExit = new Thread(this::clear, "rtd: clear the progress line");
    private volatile Phase phase = Phase.of("starting");
    private volatile boolean done;
    private boolean shown;
    private boolean hooked;
    private int columns;
    private Phase timed;
    private ProgressLine line;

    /** What the run is doing: its name, the fraction done (NaN if unknown), and the rays traced (negative: none). */
    record Phase(String name, DoubleSupplier fraction, LongSupplier rays, long startNanos) {

        /** A phase whose progress is unknown, such as reading the scene. */
        static Phase of(String name) {
            return counted(name, () -> Double.NaN);
        }

        /** A phase that knows the fraction it has done. */
        static Phase counted(String name, DoubleSupplier fraction) {
            return new Phase(name, fraction, () -> -1, System.nanoTime());
        }

        /** Rendering, with the fraction done and the rays traced so far. */
        static Phase rendering(DoubleSupplier fraction, LongSupplier rays) {
            return new Phase("rendering", fraction, rays, System.nanoTime());
        }
    }

    ProgressDisplay(PrintWriter err, IntSupplier columnsOfTerminal, long delayMillis) {
        this.err = err;
        this.columnsOfTerminal = columnsOfTerminal;
        this.delayMillis = delayMillis;
        this.thread = new Thread(this::run, "rtd-progress");
        thread.setDaemon(true);
    }

    /** Starts a display on {@code err}, a terminal; if not {@code enabled}, one that never shows anything. */
    static ProgressDisplay start(boolean enabled, PrintWriter err) {
        ProgressDisplay display = new ProgressDisplay(err, StandardStreams::columns, 1000);
        if (enabled) {
            display.thread.start();
        }
        return display;
    }

    /** The run now does {@code next}. */
    void show(Phase next) {
        phase = next;
    }

    private void run() {
        try {
            Thread.sleep(delayMillis);
            while (!done) {
                draw();
                Thread.sleep(PERIOD_MILLIS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Draws the line for the phase now running; package-private so that tests need not wait. */
    void draw() {
        if (columns == 0) {
            columns = columnsOfTerminal.getAsInt(); // starts a process: once, and not under the lock
        }
        synchronized (this) {
            if (done) {
                return;
            }
            if (!hooked) {
                hooked = addHook();
            }
            err.print("\r" + text(phase, System.nanoTime()) + "\033[K");
            err.flush();
            shown = true;
        }
    }

    private String text(Phase current, long now) {
        if (current != timed) {
            timed = current;
            line = new ProgressLine();
        }
        return line.update(current.name(), (now - current.startNanos()) / 1e9, current.fraction().getAsDouble(),
                current.rays().getAsLong(), columns);
    }

    private boolean addHook() {
        try {
            Runtime.getRuntime().addShutdownHook(clearOnExit);
            return true;
        } catch (IllegalStateException e) {
            return false; // already stopping
        }
    }

    /** Prints a line of its own, such as a warning, with the progress line out of its way. */
    synchronized void message(String line) {
        if (shown) {
            err.print(CLEAR); // the next draw shows the progress line again, below the message
        }
        err.println(line);
        err.flush();
    }

    /** Clears the line if it was shown; the shutdown hook's work. */
    private synchronized void clear() {
        done = true;
        if (shown) {
            err.print(CLEAR);
            err.flush();
            shown = false;
        }
    }

    /** Stops the display and clears its line. */
    @Override
    public void close() {
        clear();
        thread.interrupt();
        boolean remove;
        synchronized (this) {
            remove = hooked;
            hooked = false;
        }
        if (remove) {
            try {
                Runtime.getRuntime().removeShutdownHook(clearOnExit);
            } catch (IllegalStateException e) {
                // the JVM is stopping, and the hook clears the line anyway
            }
        }
    }

    /** The shutdown hook, once the line has been shown; for tests. */
    Thread shutdownHook() {
        return clearOnExit;
    }
}
