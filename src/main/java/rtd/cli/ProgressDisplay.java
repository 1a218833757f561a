package rtd.cli;

import java.io.PrintWriter;
import java.util.OptionalDouble;
import java.util.function.DoubleSupplier;
import java.util.function.IntSupplier;

/**
 * A one-line progress display on standard error, redrawn in place a few times a second: what
 * the run is doing ("reading scene.txt", "rendering", "writing out.png"), how much of it is done
 * and how long it has left. It shows only once a run has taken more than a second, and only on
 * a terminal.
 *
 * <p>The line always ends short of the terminal's last column: a line that fills it would wrap,
 * and each redraw, which returns to the start of the line with {@code \r}, would add a line.
 * It is cleared when the run ends, and when Ctrl-C stops the JVM (a shutdown hook).
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
    private TimeLeft timeLeft;

    /** What the run is doing: its name, and the fraction done (NaN if unknown); for rendering, Mrays in all. */
    record Phase(String name, DoubleSupplier fraction, double megaRays, long startNanos) {

        /** A phase whose progress is unknown, such as reading the scene. */
        static Phase of(String name) {
            return new Phase(name, () -> Double.NaN, 0, System.nanoTime());
        }

        /** A phase that knows the fraction it has done. */
        static Phase counted(String name, DoubleSupplier fraction) {
            return new Phase(name, fraction, 0, System.nanoTime());
        }

        /** Rendering {@code megaRays} million rays, with the fraction done. */
        static Phase rendering(DoubleSupplier fraction, double megaRays) {
            return new Phase("rendering", fraction, megaRays, System.nanoTime());
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
        ProgressDisplay display = new ProgressDisplay(err, Terminal::columns, 1000);
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
            timeLeft = new TimeLeft();
        }
        double seconds = (now - current.startNanos()) / 1e9;
        double fraction = current.fraction().getAsDouble();
        String rate = current.megaRays() > 0 && seconds > 0 && fraction >= 0
                ? String.format(java.util.Locale.ROOT, "%.2f Mrays/s", fraction * current.megaRays() / seconds) : null;
        OptionalDouble left = Double.isNaN(fraction) ? OptionalDouble.empty() : timeLeft.update(seconds, fraction);
        return ProgressText.line(current.name(), fraction, rate, left, seconds, columns);
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
