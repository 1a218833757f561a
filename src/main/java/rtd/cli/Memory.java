package rtd.cli;

import java.lang.management.ManagementFactory;
import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.Locale;
import java.util.Optional;

/**
 * Whether a picture fits in memory, checked before anything is allocated; amounts of memory in words; and advice
 * on Java's limit ({@code -Xmx}) that this machine can follow: never more than the memory it has.
 */
final class Memory {

    private static final long MIB = 1L << 20;
    private static final long GIB = 1L << 30;
    /** The most pixels of a Java image (an array of ints). */
    private static final long MOST_PIXELS = Integer.MAX_VALUE - 8;

    /** That a {@code width × height} picture fits a Java image and the memory left; else a misuse saying what fits. */
    static void checkImageFits(int width, int height, Scale scale) {
        long pixels = (long) width * height;
        if (pixels > MOST_PIXELS) {
            double shrink = Math.sqrt(MOST_PIXELS / (double) pixels);
            String factor = BigDecimal.valueOf(scale.factor() * shrink).round(new MathContext(3, RoundingMode.DOWN))
                    .stripTrailingZeros().toPlainString();
            throw new Misuse(String.format(Locale.ROOT, "a %d×%d image has %,d pixels; Java "
                    + "images hold at most %,d: the largest of that shape is %d×%d, or keep the view with --scale %s",
                    width, height, pixels, MOST_PIXELS, (long) (width * shrink), (long) (height * shrink), factor));
        }
        Runtime runtime = Runtime.getRuntime();
        long available = runtime.maxMemory() - (runtime.totalMemory() - runtime.freeMemory());
        long needed = pixels * (4 + 3 + 3); // the picture's ints, and 6 bytes for the encoders' copy of it
        if (needed > available) {
            String advice = xmx(needed + runtime.maxMemory(), physical())
                    .map(xmx -> "choose a smaller --width/--height, or raise the limit: java -Xmx" + xmx
                            + " -jar rtd.jar ...")
                    .orElse("choose a smaller --width/--height: this machine has " + size(physical()) + " in all");
            throw new Misuse(String.format(Locale.ROOT,
                    "a %d×%d image needs %s of memory, but Java may use only %s more here (limit %s); %s",
                    width, height, size(needed), size(available), size(runtime.maxMemory()), advice));
        }
    }

    /** {@code bytes} in a unit that shows the difference between small amounts: "16.0 MiB", not "0.0 GiB". */
    static String size(long bytes) {
        int unit = bytes >= GIB ? 3 : bytes >= MIB ? 2 : 1;
        return String.format(Locale.ROOT, "%.1f %ciB", bytes / Math.pow(1024, unit), " KMG".charAt(unit));
    }

    /** The memory of this machine (or of its container), or {@code Long.MAX_VALUE} if Java cannot tell. */
    static long physical() {
        return ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                && os.getTotalMemorySize() > 0 ? os.getTotalMemorySize() : Long.MAX_VALUE;
    }

    /** {@code -Xmx} for at least {@code bytes}: "64m", "23g", rounded up; empty if more than {@code physical}. */
    static Optional<String> xmx(long bytes, long physical) {
        long step = bytes < GIB ? 64 * MIB : GIB;
        long rounded = Math.max(1, (bytes + step - 1) / step) * step;
        return rounded > physical ? Optional.empty()
                : Optional.of(rounded < GIB ? rounded / MIB + "m" : rounded / GIB + "g");
    }

    /** What to say when Java ran out of {@code maxHeap}: more, up to 7/8 of {@code physical}, or smaller work. */
    static String outOfMemory(long maxHeap, long physical) {
        // Up to 7/8 of the machine, in whole GiB: the system and other programs need the rest.
        long wanted = Math.min(2 * maxHeap, physical / 8 * 7 / GIB * GIB);
        return (wanted > maxHeap ? xmx(wanted, physical) : Optional.<String>empty())
                .map(xmx -> "rtd: out of memory: Java may use only " + size(maxHeap) + " here; give it more, for "
                        + "example: java -Xmx" + xmx + " -jar rtd.jar ...")
                .orElse("rtd: out of memory: Java may use " + size(maxHeap) + " here, and this machine has "
                        + size(physical) + " in all; render a smaller image (--width/--height) or a scene with fewer "
                        + "objects");
    }
}
