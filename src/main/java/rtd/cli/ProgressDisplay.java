package rtd.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.OptionalDouble;
import java.util.function.DoubleSupplier;
import java.util.function.IntSupplier;
import java.util.function.LongSupplier;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * A progress line on standard error, redrawn four times a second: what the run is doing, how much is done and how
 * long it has left. It shows only on a terminal, after a second; it ends short of the last column (a full line would
 * wrap, and each {@code \r} redraw add a line); it is cleared when the run ends, also by Ctrl-C.
 */
final class ProgressDisplay implements AutoCloseable {

    private static final String CLEAR = "\r\033[K";

    private final PrintWriter err;
    private final IntSupplier columnsOfTerminal;
    private final Thread thread = new Thread(this::run, "rtd-progress");
    final Thread clearOnExit = new Thread(this::clear, "rtd: clear the progress line");
    private volatile Phase phase = Phase.of("starting");
    private volatile boolean done;
    private boolean shown;
    private int columns;

    ProgressDisplay(PrintWriter err, IntSupplier columnsOfTerminal) {
        this.err = err;
        this.columnsOfTerminal = columnsOfTerminal;
        thread.setDaemon(true);
    }

    /** A display on {@code err}, a terminal; if not {@code enabled}, one that never shows anything. */
    static ProgressDisplay start(boolean enabled, PrintWriter err) {
        ProgressDisplay display = new ProgressDisplay(err, StandardStreams::columns);
        try {
            if (enabled) {
                Runtime.getRuntime().addShutdownHook(display.clearOnExit);
                display.thread.start();
            }
        } catch (IllegalStateException e) {
            // already stopping (Ctrl-C during --watch): no line to clear then
        }
        return display;
    }

    void show(Phase next) {
        phase = next;
    }

    private void run() {
        try {
            for (Thread.sleep(1000); !done; Thread.sleep(250)) {
                draw();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    void draw() {
        if (columns == 0) {
            columns = columnsOfTerminal.getAsInt(); // starts a process: once, and not under the lock
        }
        synchronized (this) {
            if (!done) {
                Phase now = phase;
                err.print("\r" + now.line((System.nanoTime() - now.startNanos()) / 1e9, columns) + "\033[K");
                err.flush();
                shown = true;
            }
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

    private synchronized void clear() {
        done = true;
        if (shown) {
            err.print(CLEAR);
            err.flush();
            shown = false;
        }
    }

    @Override
    public void close() {
        clear();
        thread.interrupt();
        try {
            Runtime.getRuntime().removeShutdownHook(clearOnExit); // false, and harmless, if never added
        } catch (IllegalStateException e) {
            // the JVM is stopping, and the hook clears the line anyway
        }
    }

    /**
     * What the run is doing: its name, the fraction done (NaN if unknown), the rays traced (negative: none), and the
     * recent (seconds, fraction) pairs: the time left uses the rate of the last third of the time so far, as rays get
     * cheaper while the JIT compiles.
     */
    record Phase(String name, DoubleSupplier fraction, LongSupplier rays, long startNanos, List<double[]> recent) {

        Phase(String name, DoubleSupplier fraction, LongSupplier rays) {
            this(name, fraction, rays, System.nanoTime(), new ArrayList<>(List.of(new double[] {0, 0})));
        }

        static Phase of(String name) {
            return counted(name, () -> Double.NaN);
        }

        static Phase counted(String name, DoubleSupplier fraction) {
            return new Phase(name, fraction, () -> -1);
        }

        String line(double seconds, int columns) {
            double done = fraction.getAsDouble();
            long traced = rays.getAsLong();
            String rate = traced >= 0 && seconds > 0
                    ? String.format(Locale.ROOT, "%.2f Mrays/s", traced / seconds / 1e6) : null;
            OptionalDouble left = Double.isNaN(done) ? OptionalDouble.empty() : timeLeft(seconds, done);
            return fit(name, done, rate, left, seconds, columns);
        }

        /** The time left after {@code seconds} with {@code fraction} (0 to 1) of the work done; empty if unknown. */
        OptionalDouble timeLeft(double seconds, double fraction) {
            recent.add(new double[] {seconds, fraction});
            double window = Math.max(1.0, seconds / 3);
            while (recent.size() > 2 && seconds - recent.get(1)[0] >= window) {
                recent.remove(0);
            }
            double[] then = recent.get(0);
            double rate = (fraction - then[1]) / (seconds - then[0]);
            if (!(fraction > 0) || seconds < 1.5 && fraction < 0.05 || !(rate > 0)) {
                return OptionalDouble.empty();
            }
            return OptionalDouble.of((1 - Math.min(1, fraction)) / rate);
        }

        /** The line in {@code columns − 1}: what does not fit goes first: the rate, "about", "left", the name. */
        static String fit(String name, double fraction, String rate, OptionalDouble left, double seconds, int columns) {
            int room = Math.max(1, columns - 1);
            boolean unknown = Double.isNaN(fraction);
            String percent = unknown ? null
                    : String.format(Locale.ROOT, "%3d%%", Math.round(100 * Math.max(0, Math.min(1, fraction)) - 0.5));
            String span = left.isPresent() ? duration(left.getAsDouble()) : unknown ? duration(seconds) : null;
            String full = join(name + (unknown ? "…" : ""), percent, rate, left.isPresent() ? "about " + span + " left"
                    : span);
            String shorter = join(name, percent, left.isPresent() ? span + " left" : span);
            String tail = join(percent, span);
            int nameRoom = room - tail.length() - 2;
            if (full.length() <= room || shorter.length() <= room) {
                return full.length() <= room ? full : shorter;
            } else if (nameRoom >= 4) {
                String cut = name.length() <= nameRoom ? name : "…" + name.substring(name.length() - nameRoom + 1);
                return tail.isEmpty() ? cut : cut + "  " + tail;
            }
            return tail.length() <= room ? tail : tail.substring(0, room);
        }

        /** "7 s", "2 min", "1 h 5 min": coarser the longer, so that the line does not flicker. */
        static String duration(double seconds) {
            long s = Math.round(seconds);
            long minutes = Math.round(seconds / 60);
            return s < 60 ? s + " s" : minutes < 60 ? minutes + " min" : minutes / 60 + " h " + minutes % 60 + " min";
        }

        private static String join(String... parts) {
            return Stream.of(parts).filter(Objects::nonNull).collect(Collectors.joining("  "));
        }
    }
}
