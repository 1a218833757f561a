package rtd.cli;

import java.nio.file.Path;
import java.util.Formatter;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import rtd.accel.Accelerator;
import rtd.render.WorkCount;
import rtd.scene.Scene;

/** {@code --stats}: the wall time of each phase of a run, and the report of them and of the work per ray. */
final class StatsReport {

    private static final String LINE = "%-7s %8.3f s  %s%n";

    private final Map<String, Double> seconds = new LinkedHashMap<>();
    private long phaseStart = System.nanoTime();

    /** Ends the running phase under {@code name} and starts the next. */
    void endPhase(String name) {
        long now = System.nanoTime();
        seconds.put(name, (now - phaseStart) / 1e9);
        phaseStart = now;
    }

    String format(Scene scene, Accelerator accelerator, WorkCount work, int threads, Path output) {
        double render = seconds.getOrDefault("render", 0.0);
        Formatter text = new Formatter(Locale.ROOT);
        text.format(LINE, "parse", seconds.get("parse"), WorkCount.count(scene.objects().size(), "object"));
        if (seconds.containsKey("export")) {
            text.format(LINE, "export", seconds.get("export"), "the scene for POV-Ray (--export-pov)");
        }
        text.format(LINE, "build", seconds.get("build"), accelerator.built().get());
        text.format(LINE, "render", render, String.format(Locale.ROOT, "%,d rays%s on %d thread%s, %.2f Mrays/s",
                work.rays(), raysByKind(work), threads, threads == 1 ? "" : "s", work.rays() / render / 1e6));
        if (work.answeredBy().values().stream().filter(rays -> rays > 0).count() > 1) {
            text.format("           %s%n", answeredBy(work));
        }
        text.format(LINE, "write", seconds.get("write"), output);
        text.format(LINE, "total", seconds.values().stream().mapToDouble(Double::doubleValue).sum(),
                "from reading the scene to the written picture; the JVM's start is not counted");
        text.format("per ray: %.2f intersection tests%s", work.testsPerRay(), byKind(work));
        text.format(accelerator.walksTree() ? ", %.2f BVH nodes visited%n" : "%n", work.nodesPerRay());
        return text.toString();
    }

    /** " (2,073,600 camera, 1,234 shadow, ...)" when secondary rays were followed. */
    private static String raysByKind(WorkCount work) {
        return work.secondaryRays().isEmpty() ? "" : work.secondaryRays().entrySet().stream()
                .map(kind -> String.format(Locale.ROOT, ", %,d %s", kind.getValue(), kind.getKey()))
                .collect(Collectors.joining("", String.format(Locale.ROOT, " (%,d camera", work.cameraRays()), ")"));
    }

    /** "2,073,600 answered by the view grid, 2,717,106 by the light grids, 2,324,364 by the BVH", so. */
    private static String answeredBy(WorkCount work) {
        return Stream.of("view grid", "light grids", "BVH")
                .filter(structure -> work.answeredBy().getOrDefault(structure, 0L) > 0)
                .map(structure -> String.format(Locale.ROOT, "%,d by the %s", work.answeredBy().get(structure),
                        structure))
                .collect(Collectors.joining(", ")).replaceFirst(" by ", " answered by ");
    }

    /** " (12.50 sphere, 1.00 plane)" when the scene has more than one kind of object. */
    private static String byKind(WorkCount work) {
        return work.testsByKind().size() < 2 ? "" : work.testsByKind().keySet().stream()
                .map(kind -> String.format(Locale.ROOT, "%.2f %s", work.testsPerRay(kind), kind))
                .collect(Collectors.joining(", ", " (", ")"));
    }
}
