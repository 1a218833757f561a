package rtd.cli;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import rtd.render.WorkCount;
import rtd.scene.Scene;

/** {@code --stats}: the wall time of each phase of a run, one after the other, and the report of them and of the work per ray. */
final class StatsReport {

    private final Map<String, Double> seconds = new LinkedHashMap<>();
    private long phaseStart = System.nanoTime();

    /** Ends the running phase under {@code name} and starts the next. */
    void endPhase(String name) {
        long now = System.nanoTime();
        seconds.put(name, (now - phaseStart) / 1e9);
        phaseStart = now;
    }

    /** The report of the phases so far, for {@code scene} rendered with {@code accelerator} (null: the paper's loop). */
    String format(Scene scene, Accelerator accelerator, WorkCount work, int threads, Path output) {
        double renderSeconds = seconds.getOrDefault("render", 0.0);
        StringBuilder text = new StringBuilder();
        line(text, "parse", seconds.get("parse"), count(scene.objects().size(), "object"));
        if (seconds.containsKey("export")) {
            line(text, "export", seconds.get("export"), "the scene for POV-Ray (--export-pov)");
        }
        line(text, "build", seconds.get("build"), accelerator == null
                ? "no BVH: the paper's loop tests every object" : accelerator.built().get());
        line(text, "render", renderSeconds, String.format(Locale.ROOT, "%,d rays%s on %d thread%s, %.2f Mrays/s",
                work.rays(), raysByKind(work), threads, threads == 1 ? "" : "s", work.rays() / renderSeconds / 1e6));
        if (work.answeredBy().values().stream().filter(rays -> rays > 0).count() > 1) {
            text.append(String.format(Locale.ROOT, "           %s%n", answeredBy(work)));
        }
        line(text, "write", seconds.get("write"), output.toString());
        double total = seconds.values().stream().mapToDouble(Double::doubleValue).sum();
        line(text, "total", total, "from reading the scene to the written picture; the JVM's start is not counted");
        text.append(String.format(Locale.ROOT, "per ray: %.2f intersection tests%s", work.testsPerRay(), byKind(work)));
        text.append(accelerator != null && accelerator.walksTree()
                ? String.format(Locale.ROOT, ", %.2f BVH nodes visited%n", work.nodesPerRay()) : String.format("%n"));
        return text.toString();
    }

    /** " (2,073,600 camera, 1,234 shadow, ...)" when secondary rays were followed. */
    private static String raysByKind(WorkCount work) {
        if (work.secondaryRays().isEmpty()) {
            return "";
        }
        StringBuilder kinds = new StringBuilder(String.format(Locale.ROOT, " (%,d camera", work.cameraRays()));
        for (Map.Entry<String, Long> kind : work.secondaryRays().entrySet()) {
            kinds.append(String.format(Locale.ROOT, ", %,d %s", kind.getValue(), kind.getKey()));
        }
        return kinds.append(')').toString();
    }

    /** "2,073,600 answered by the view grid, 2,718,977 by the light grids, 2,322,493 by the BVH", in that order. */
    private static String answeredBy(WorkCount work) {
        StringBuilder text = new StringBuilder();
        for (String structure : new String[] {"view grid", "light grids", "BVH"}) {
            Long rays = work.answeredBy().get(structure);
            if (rays != null && rays > 0) {
                text.append(String.format(Locale.ROOT, text.length() == 0 ? "%,d answered by the %s" : ", %,d by the %s",
                        rays, structure));
            }
        }
        return text.toString();
    }

    /** "1 object", "2,000 objects". */
    static String count(long n, String thing) {
        return count(n, thing, thing + "s");
    }

    /** "1 entry", "2,000 entries". */
    static String count(long n, String one, String many) {
        return String.format(Locale.ROOT, "%,d %s", n, n == 1 ? one : many);
    }

    /** " (12.50 sphere, 1.00 plane)" when the scene has more than one kind of object. */
    private static String byKind(WorkCount work) {
        if (work.testsByKind().size() < 2) {
            return "";
        }
        StringBuilder kinds = new StringBuilder();
        work.testsByKind().keySet().forEach(kind -> kinds.append(kinds.length() == 0 ? " (" : ", ")
                .append(String.format(Locale.ROOT, "%.2f %s", work.testsPerRay(kind), kind)));
        return kinds.append(')').toString();
    }

    private static void line(StringBuilder text, String phase, double seconds, String detail) {
        text.append(String.format(Locale.ROOT, "%-7s %8.3f s  %s%n", phase, seconds, detail));
    }
}
