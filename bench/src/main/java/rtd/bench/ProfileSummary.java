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
 * joined by {@code ;}, then its number of samples). The annotation of the deepest Java frames says
 * how they ran: {@code _[0]} interpreted, {@code _[1]} C1-compiled, {@code _[j]} C2-compiled,
 * {@code _[i]} inlined into the frame above; frames further up are mostly marked {@code _[j]},
 * whatever they are, so only the deepest ones are read. {@code bench/profile.sh} runs the profiler
 * and then this.
 *
 * <p>Each sample goes to one share: the JIT compilers' threads, the collector (its threads, and
 * allocation's slow path), the kernel, native libraries, the JVM's own code under Java (its
 * runtime, counters, deoptimisation), rtd's own code by how it ran (C2-compiled code is the fast
 * one; interpreted and C1 code is what a first run pays while the JIT catches up), the JDK's Java
 * code, and the rest of the JVM. A method inlined into another runs as that one was compiled; it
 * counts as rtd's code if either of the two is rtd's (Math.sqrt inlined into rtd's test, or rtd's
 * lambda inlined into a stream). Then the methods of rtd that the samples were taken in most.
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
        JDK("the JDK's Java code (the PNG writer, picocli, collections)"),
        C2("C2 compiling"),
        C1("C1 compiling"),
        GC("the collector (its threads, and allocation's slow path)"),
        KERNEL("the kernel (page faults, reading the file, threads)"),
        NATIVE("native libraries (zlib for the PNG, libm)"),
        JVM("the JVM's other work (its runtime under Java, class loading, start)");

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
            String trimmed = line.trim();
            int space = trimmed.lastIndexOf(' ');
            if (space < 0) {
                continue;
            }
            long samples;
            try {
                samples = Long.parseLong(trimmed.substring(space + 1));
            } catch (NumberFormatException notACount) {
                continue; // not a line of samples
            }
            String[] frames = trimmed.substring(0, space).split(";");
            total += samples;
            shares.merge(shareOf(frames), samples, Long::sum);
            String method = deepestRtdMethod(frames);
            if (method != null) {
                ownSamples.merge(method, samples, Long::sum);
            }
        }
        print(shares, ownSamples, total, top);
    }

    /** The share a stack belongs to, from its threads' frames and its deepest frames. */
    static Share shareOf(String[] frames) {
        String stack = String.join(";", frames);
        if (stack.contains("C2Compiler::")) {
            return Share.C2;
        }
        if (stack.contains("Compiler::compile_method") || stack.contains("Compilation::")) {
            return Share.C1;
        }
        if (isCollector(stack)) {
            return Share.GC;
        }
        String leaf = frames[frames.length - 1];
        if (leaf.endsWith("_[k]")) {
            return Share.KERNEL;
        }
        int java = deepestJavaFrame(frames);
        if (java < frames.length - 1 || java < 0) { // no Java frame, or native code under the deepest
            return isLibrary(leaf) ? Share.NATIVE : Share.JVM;
        }
        int host = hostOf(frames, java);
        if (!frames[java].startsWith("rtd/") && !frames[host].startsWith("rtd/")) {
            return Share.JDK;
        }
        return switch (frames[host].substring(frames[host].length() - 4)) {
            case "_[0]" -> Share.RTD_INTERPRETED;
            case "_[1]" -> Share.RTD_C1;
            default -> Share.RTD_C2;
        };
    }

    /** Whether a stack is the collector's: G1's (the default), or the serial or parallel collector's. */
    private static boolean isCollector(String stack) {
        return stack.contains("G1") || stack.contains("PSScavenge") || stack.contains("PSParallelCompact")
                || stack.contains("DefNewGeneration") || stack.contains("SerialHeap") || stack.contains("GenCollectedHeap")
                || stack.contains("GCTaskThread");
    }

    /** Whether a frame is a native library's, named by its file (zlib's, libm's). */
    private static boolean isLibrary(String frame) {
        return frame.startsWith("/") || frame.startsWith("lib");
    }

    /** The frame that frame {@code i} runs as part of: itself, or the compiled frame it was inlined into. */
    private static int hostOf(String[] frames, int i) {
        int k = i;
        while (k > 0 && frames[k].endsWith("_[i]")) {
            k--;
        }
        return k;
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

    /** The deepest frame of rtd's code, without its annotation, or null if the stack has none. */
    private static String deepestRtdMethod(String[] frames) {
        for (int i = frames.length - 1; i >= 0; i--) {
            if (frames[i].startsWith("rtd/") && isJava(frames[i])) {
                return frames[i].substring(0, frames[i].length() - 4).replace('/', '.')
                        .replaceAll("[./]0x[0-9a-f]+", ""); // a lambda's class carries its address in this run
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
