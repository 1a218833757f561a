package rtd.cli;

import java.lang.management.ManagementFactory;
import java.util.Locale;
import java.util.Optional;

/**
 * Amounts of memory in words, and advice on Java's limit ({@code -Xmx}) that this machine can
 * follow: never more than the memory it has.
 */
final class Memory {

    private static final long KIB = 1L << 10;
    private static final long MIB = 1L << 20;
    private static final long GIB = 1L << 30;

    private Memory() {
    }

    /** {@code bytes} in a unit that shows the difference between small amounts: "16.0 MiB", not "0.0 GiB". */
    static String size(long bytes) {
        if (bytes >= GIB) {
            return String.format(Locale.ROOT, "%.1f GiB", bytes / (double) GIB);
        }
        if (bytes >= MIB) {
            return String.format(Locale.ROOT, "%.1f MiB", bytes / (double) MIB);
        }
        return String.format(Locale.ROOT, "%.1f KiB", bytes / (double) KIB);
    }

    /** The memory of this machine (or of its container), or {@code Long.MAX_VALUE} if Java cannot tell. */
    static long physical() {
        if (ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                && os.getTotalMemorySize() > 0) {
            return os.getTotalMemorySize();
        }
        return Long.MAX_VALUE;
    }

    /**
     * The value of {@code -Xmx} for at least {@code bytes}, rounded up (to 64 MiB below 1 GiB, to
     * whole GiB above): "64m", "23g"; empty if that is more than the machine's {@code physical} memory.
     */
    static Optional<String> xmx(long bytes, long physical) {
        long rounded = bytes < GIB ? roundUp(bytes, 64 * MIB) : roundUp(bytes, GIB);
        if (rounded > physical) {
            return Optional.empty();
        }
        return Optional.of(rounded < GIB ? rounded / MIB + "m" : rounded / GIB + "g");
    }

    /**
     * What to say when Java ran out of memory with a limit of {@code maxHeap} on a machine with
     * {@code physical} bytes: twice the limit, or 7/8 of the machine's memory if that is less but
     * still more than the limit; otherwise that the work must be smaller.
     */
    static String outOfMemory(long maxHeap, long physical) {
        // Up to 7/8 of the machine, in whole GiB: the system and other programs need the rest.
        long wanted = Math.min(2 * maxHeap, physical / 8 * 7 / GIB * GIB);
        Optional<String> advice = wanted > maxHeap ? xmx(wanted, physical) : Optional.empty();
        if (advice.isPresent()) {
            return "rtd: out of memory: Java may use only " + size(maxHeap) + " here; give it more, for example: java -Xmx"
                    + advice.get() + " -jar rtd.jar ...";
        }
        return "rtd: out of memory: Java may use " + size(maxHeap) + " here, and this machine has " + size(physical)
                + " in all; render a smaller image (--width/--height) or a scene with fewer objects";
    }

    private static long roundUp(long bytes, long step) {
        return Math.max(1, (bytes + step - 1) / step) * step;
    }
}
