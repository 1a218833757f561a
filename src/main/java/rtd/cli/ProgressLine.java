package rtd.cli;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;

/**
 * The words of the progress line for one phase, fitted to a terminal of any width: percent done, for a render
 * the rays traced per second as {@code --stats} counts them (all rays, over the render so far), and the time left.
 *
 * <p>The time left is the work left over the rate of the last third of the time so far (at least the last
 * second): rays get cheaper as the JIT compiles, so the rate since the start would promise too long, while the
 * rate of a longer stretch does not swing with the cost of the last few rows. It says nothing until
 * {@value #MIN_SECONDS} s or {@value #MIN_FRACTION} of the work have given it something to go on.
 */
final class ProgressLine {

    static final double MIN_WINDOW = 1.0;
    static final double MIN_SECONDS = 1.5;
    static final double MIN_FRACTION = 0.05;

    /** (seconds, fraction) of the updates within the window, and the last one before it. */
    private final ArrayDeque<double[]> recent = new ArrayDeque<>(List.of(new double[] {0, 0}));

    /** The time left after {@code seconds} with {@code fraction} (0 to 1) of the work done; empty if unknown. */
    OptionalDouble timeLeft(double seconds, double fraction) {
        recent.addLast(new double[] {seconds, fraction});
        double window = Math.max(MIN_WINDOW, seconds / 3);
        while (recent.size() > 2 && seconds - secondOldest()[0] >= window) {
            recent.removeFirst();
        }
        double[] then = recent.peekFirst();
        double rate = (fraction - then[1]) / (seconds - then[0]);
        if (!(fraction > 0) || seconds < MIN_SECONDS && fraction < MIN_FRACTION || !(rate > 0)) {
            return OptionalDouble.empty();
        }
        return OptionalDouble.of((1 - Math.min(1, fraction)) / rate);
    }

    private double[] secondOldest() {
        return recent.stream().skip(1).findFirst().orElseThrow();
    }

    /**
     * The line for phase {@code name} after {@code seconds}, with {@code fraction} done (NaN if unknown) and
     * {@code rays} traced (negative if it traces none), at most {@code columns − 1} characters long.
     */
    String update(String name, double seconds, double fraction, long rays, int columns) {
        String rate = rays >= 0 && seconds > 0 ? String.format(Locale.ROOT, "%.2f Mrays/s", rays / seconds / 1e6) : null;
        OptionalDouble left = Double.isNaN(fraction) ? OptionalDouble.empty() : timeLeft(seconds, fraction);
        return fit(name, fraction, rate, left, seconds, columns);
    }

    /**
     * The line of percent done, {@code rate} (or null) and time {@code left} (or, for a phase of unknown length,
     * the {@code seconds} it has run), in {@code columns − 1}: what does not fit goes first, the rate, then
     * "about", then the start of the name.
     */
    static String fit(String name, double fraction, String rate, OptionalDouble left, double seconds, int columns) {
        int room = Math.max(1, columns - 1);
        String percent = Double.isNaN(fraction) ? null
                : String.format(Locale.ROOT, "%3d%%", Math.round(100 * Math.max(0, Math.min(1, fraction)) - 0.5));
        String time = left.isPresent() ? "about " + duration(left.getAsDouble()) + " left"
                : Double.isNaN(fraction) ? duration(seconds) : null;
        String full = join(name + (Double.isNaN(fraction) ? "…" : ""), percent, rate, time);
        if (full.length() <= room) {
            return full;
        }
        String shorter = join(name, percent, null, time == null ? null : time.replace("about ", ""));
        if (shorter.length() <= room) {
            return shorter;
        }
        String tail = join(percent, time == null ? null : time.replace("about ", "").replace(" left", ""));
        int nameRoom = room - tail.length() - 2;
        if (nameRoom >= 4) {
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

    /** The parts that are there, two spaces apart. */
    private static String join(String... parts) {
        List<String> kept = new ArrayList<>();
        for (String part : parts) {
            if (part != null) {
                kept.add(part);
            }
        }
        return String.join("  ", kept);
    }
}
