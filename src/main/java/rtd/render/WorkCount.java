package rtd.render;

import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import rtd.geometry.IGeometry;

/**
 * How much work tracing took, which {@code --stats} prints per ray, so a student sees N tests per ray without the
 * hierarchy and about log N with it. The counts by name are kept sorted and unmodifiable.
 *
 * @param testsByKind   intersection tests per kind of object ("sphere", "triangle", ...)
 * @param nodesVisited  bounding-volume nodes visited
 * @param secondaryRays the shader's rays by kind ("shadow", "reflected", ...), which {@code rays} counts too
 * @param answeredBy    the rays by what found their hits ("view grid", "BVH", ...), where a tracer says
 */
public record WorkCount(long rays, Map<String, Long> testsByKind, long nodesVisited, Map<String, Long> secondaryRays,
        Map<String, Long> answeredBy) {

    public static final WorkCount NONE = new WorkCount(0, Map.of(), 0);

    public WorkCount {
        testsByKind = Collections.unmodifiableMap(new TreeMap<>(testsByKind));
        secondaryRays = Collections.unmodifiableMap(new TreeMap<>(secondaryRays));
        answeredBy = Collections.unmodifiableMap(new TreeMap<>(answeredBy));
    }

    public WorkCount(long rays, Map<String, Long> testsByKind, long nodesVisited) {
        this(rays, testsByKind, nodesVisited, Map.of(), Map.of());
    }

    /**
     * This work, and {@code secondary} rays more by kind (which {@link #rays} already counts: the tracer traced them).
     */
    public WorkCount plusSecondary(Map<String, Long> secondary) {
        return new WorkCount(rays, testsByKind, nodesVisited, sum(secondaryRays, secondary, 1), answeredBy);
    }

    /** This work, all its rays answered by {@code structure}: a tracer labels its own so, before adding another's. */
    public WorkCount answeredBy(String structure) {
        return new WorkCount(rays, testsByKind, nodesVisited, secondaryRays, Map.of(structure, rays));
    }

    /** The rays the camera made: all rays traced but the secondary ones. */
    public long cameraRays() {
        return rays - total(secondaryRays);
    }

    /** {@code a} plus {@code b} times {@code factor}, by name. */
    private static Map<String, Long> sum(Map<String, Long> a, Map<String, Long> b, long factor) {
        Map<String, Long> sum = new TreeMap<>(a);
        for (Map.Entry<String, Long> entry : b.entrySet()) { // a loop: a first run links no lambda here
            sum.put(entry.getKey(), sum.getOrDefault(entry.getKey(), 0L) + entry.getValue() * factor);
        }
        return sum;
    }

    /** The paper's loop's work for {@code rays} rays: each a test of each of {@code objects}. */
    public static WorkCount testsOf(List<IGeometry> objects, long rays) {
        Map<String, Long> tests = new TreeMap<>();
        objects.forEach(object -> tests.merge(object.kind(), 1L, Long::sum));
        return new WorkCount(1, tests, 0).times(rays);
    }

    public WorkCount times(long factor) {
        return new WorkCount(rays * factor, sum(Map.of(), testsByKind, factor), nodesVisited * factor,
                sum(Map.of(), secondaryRays, factor), sum(Map.of(), answeredBy, factor));
    }

    public WorkCount plus(WorkCount other) {
        return new WorkCount(rays + other.rays, sum(testsByKind, other.testsByKind, 1),
                nodesVisited + other.nodesVisited, sum(secondaryRays, other.secondaryRays, 1),
                sum(answeredBy, other.answeredBy, 1));
    }

    public long intersectionTests() {
        return total(testsByKind);
    }

    private static long total(Map<String, Long> counts) {
        long total = 0;
        for (long count : counts.values()) {
            total += count;
        }
        return total;
    }

    public double testsPerRay() {
        return rays == 0 ? 0 : (double) intersectionTests() / rays;
    }

    public double testsPerRay(String kind) {
        return rays == 0 ? 0 : (double) testsByKind.getOrDefault(kind, 0L) / rays;
    }

    public double nodesPerRay() {
        return rays == 0 ? 0 : (double) nodesVisited / rays;
    }

    /** A count for {@code --stats}, with its noun: "1 node", "2,048 nodes". */
    public static String count(long n, String thing) {
        return count(n, thing, thing + "s");
    }

    /** A count for {@code --stats}, with its noun, {@code one} or {@code many}: "1 entry", "2 entries". */
    public static String count(long n, String one, String many) {
        return String.format(Locale.ROOT, "%,d %s", n, n == 1 ? one : many);
    }
}
