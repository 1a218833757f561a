package rtd.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Says where the CPU time of a profiled run went, from the samples async-profiler wrote in its
 * "collapsed" form with annotated frames ({@code collapsed,ann}: one line per stack, its frames
 * joined by {@code ;}, then its number of samples; a Java frame ends in {@code _[0]} interpreted,
 * {@code _[1]} C1-compiled, {@code _[j]} C2-compiled, {@code _[i]} inlined into the frame above
 * it). {@code bench/profile.sh} runs the profiler and then this.
 *
 * <p>Each sample goes to one share: the JIT compilers' threads, the collector's, the kernel,
 * rtd's own code by how it ran (C2-compiled code is the fast one; interpreted and C1 code is
 * what a first run pays while the JIT catches up), the JDK's Java code, and the rest of the
 * JVM. Then the methods of rtd that the samples were taken in most.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar rtd.bench.ProfileSummary bench/out/profile.collapsed [TOP]
 * </pre>
 */
public final class ProfileSummary {

    /** The shares, in the order they are printed. */
    enum Share {
        RTD_C2("rtd's code, C2-compiled"),
        RTD_C1("rtd's code, C1-compiled"),
        RTD_INTERPRETED("rtd's code, interpreted"),
        JDK("the JDK's Java code (the PNG writer, picocli, and Math or collections called from rtd)"),
        C2("C2 compiling"),
        C1("C1 compiling"),
        GC("garbage collection"),
        KERNEL("the kernel (page faults, reading the file, threads)"),
        NATIVE("native libraries (zlib for the PNG, libm)"),
        JVM("the JVM's other work (class loading, start, stubs)");

        final String label;

        Share(String label) {
            this.label = label;
        }
    }

    private ProfileSummary() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 1) {
            System.err.println("usage: ProfileSummary COLLAPSED_FILE [TOP]");
            System.exit(2);
        }
        int top = args.length > 1 ? Integer.parseInt(args[1]) : 20;
        Map<Share, Long> shares = new EnumMap<>(Share.class);
        Map<String, Long> ownSamples = new HashMap<>();
        long total = 0;
        for (String line : Files.readAllLines(Path.of(args[0]))) {
            int space = line.lastIndexOf(' ');
            if (space < 0) {
                continue;
            }
            long samples = Long.parseLong(line.substring(space + 1).trim());
            String[] frames = line.substring(0, space).split(";");
            total += samples;
            shares.merge(shareOf(frames), samples, Long::sum);
            String method = deepestRtdMethod(frames);
            if (method != null) {
                ownSamples.merge(method, samples, Long::sum);
            }
        }
        print(shares, ownSamples, total, top);
    }

    /** The share a stack belongs to, from its threads' frames and its deepest frame. */
    static Share shareOf(String[] frames) {
        String stack = String.join(";", frames);
        if (stack.contains("C2Compiler::")) {
            return Share.C2;
        }
        if (stack.contains("Compilation::") || stack.contains("C1_")) {
            return Share.C1;
        }
        if (stack.contains("G1") || stack.contains("GCTaskThread") || stack.contains("WorkerThread::run")) {
            return Share.GC;
        }
        String leaf = frames[frames.length - 1];
        if (leaf.endsWith("_[k]")) {
            return Share.KERNEL;
        }
        int java = deepestJavaFrame(frames);
        if (java < 0) {
            return leaf.startsWith("/") || leaf.startsWith("lib") ? Share.NATIVE : Share.JVM;
        }
        if (java < frames.length - 1 && (leaf.startsWith("/") || leaf.startsWith("lib"))) {
            return Share.NATIVE; // a library called from Java: zlib under the PNG writer, libm's pow
        }
        if (!frames[java].startsWith("rtd/")) {
            return Share.JDK;
        }
        String tier = tierOf(frames, java);
        return switch (tier) {
            case "_[0]" -> Share.RTD_INTERPRETED;
            case "_[1]" -> Share.RTD_C1;
            default -> Share.RTD_C2;
        };
    }

    /** The index of the deepest frame that is Java code (annotated), or −1. */
    private static int deepestJavaFrame(String[] frames) {
        for (int i = frames.length - 1; i >= 0; i--) {
            if (isJava(frames[i])) {
                return i;
            }
        }
        return -1;
    }

    private static boolean isJava(String frame) {
        return frame.endsWith("_[0]") || frame.endsWith("_[1]") || frame.endsWith("_[j]") || frame.endsWith("_[i]");
    }

    /** How frame {@code i} ran: an inlined frame runs as the compiled frame it was inlined into. */
    private static String tierOf(String[] frames, int i) {
        for (int k = i; k >= 0; k--) {
            if (isJava(frames[k]) && !frames[k].endsWith("_[i]")) {
                return frames[k].substring(frames[k].length() - 4);
            }
        }
        return "_[j]";
    }

    /** The deepest frame of rtd's code, without its annotation, or null if the stack has none. */
    private static String deepestRtdMethod(String[] frames) {
        for (int i = frames.length - 1; i >= 0; i--) {
            if (frames[i].startsWith("rtd/") && isJava(frames[i])) {
                return frames[i].substring(0, frames[i].length() - 4).replace('/', '.');
            }
        }
        return null;
    }

    private static void print(Map<Share, Long> shares, Map<String, Long> ownSamples, long total, int top) {
        System.out.printf(Locale.ROOT, "%,d samples (one per millisecond of CPU, on every thread)%n", total);
        for (Share share : Share.values()) {
            long samples = shares.getOrDefault(share, 0L);
            System.out.printf(Locale.ROOT, "  %5.1f %%  %s%n", percent(samples, total), share.label);
        }
        System.out.printf(Locale.ROOT, "%nrtd's methods that the samples were taken in (or under, outside rtd) most:%n");
        List<Map.Entry<String, Long>> methods = ownSamples.entrySet().stream()
                .sorted(Map.Entry.<String, Long>comparingByValue().reversed()).limit(top).toList();
        for (Map.Entry<String, Long> method : methods) {
            System.out.printf(Locale.ROOT, "  %5.1f %%  %s%n", percent(method.getValue(), total), method.getKey());
        }
    }

    private static double percent(long part, long total) {
        return total == 0 ? 0 : 100.0 * part / total;
    }
}
