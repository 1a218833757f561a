package rtd.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;

/** The words of the progress line, made to fit a terminal of any width. */
final class ProgressText {

    private ProgressText() {
    }

    /**
     * The line for phase {@code name}: percent done (unless {@code fraction} is NaN), the
     * {@code rate} (or null), the time {@code left} (or, for a phase of unknown length, the
     * {@code seconds} it has run), at most {@code columns − 1} characters long. What does not fit
     * goes first: the rate, then "about", then the start of the name.
     */
    static String line(String name, double fraction, String rate, OptionalDouble left, double seconds, int columns) {
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
        String shortTime = time == null ? null : time.replace("about ", "").replace(" left", "");
        String tail = String.join("  ", java.util.stream.Stream.of(percent, shortTime).filter(p -> p != null).toList());
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
        if (s < 60) {
            return s + " s";
        }
        long minutes = Math.round(seconds / 60);
        if (minutes < 60) {
            return minutes + " min";
        }
        return minutes / 60 + " h " + minutes % 60 + " min";
    }

    private static String join(String name, String... parts) {
        List<String> kept = new ArrayList<>();
        kept.add(name);
        for (String part : parts) {
            if (part != null) {
                kept.add(part);
            }
        }
        return String.join("  ", kept);
    }
}
