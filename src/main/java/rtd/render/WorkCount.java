package rtd.render;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import rtd.geometry.IGeometry;

/**
 * How much work tracing took: rays, intersection tests by kind of object, and bounding-volume
 * nodes visited. {@code --stats} prints it per ray, so a student sees N tests per ray without
 * the hierarchy and about log N with it.
 *
 * @param rays         the rays traced
 * @param testsByKind  intersection tests per kind of object ("sphere", "triangle", ...)
 * @param nodesVisited bounding-volume nodes visited
 * @param secondaryRays the shader's rays by kind ("shadow", "reflected", ...), which {@code rays} counts too
 * @param answeredBy   the rays by what found their hits ("view grid", "BVH", ...), where a tracer says
 */
public record WorkCount(long rays, Map<String, Long> testsByKind, long nodesVisited, Map<String, Long> secondaryRays,
        Map<String, Long> answeredBy) {

    /** No work at all. */
    public static final WorkCount NONE = new WorkCount(0, Map.of(), 0);

    /** Keeps unmodifiable, sorted copies of the counts. */
    public WorkCount {
        testsByKind = Collections.unmodifiableMap(new TreeMap<>(testsByKind));
        secondaryRays = Collections.unmodifiableMap(new TreeMap<>(secondaryRays));
        answeredBy = Collections.unmodifiableMap(new TreeMap<>(answeredBy));
    }

    /** Work without secondary rays counted apart. */
    public WorkCount(long rays, Map<String, Long> testsByKind, long nodesVisited) {
        this(rays, testsByKind, nodesVisited, Map.of(), Map.of());
    }

    /** This work, and {@code secondary} rays more by kind (which {@link #rays} already counts: the tracer traced them). */
    public WorkCount plusSecondary(Map<String, Long> secondary) {
        return new WorkCount(rays, testsByKind, nodesVisited, sum(secondaryRays, secondary), answeredBy);
    }

    /**
     * This work, with all its rays answered by {@code structure} ("view grid", "BVH", ...): a
     * tracer labels its own work so, before it adds another's.
     */
    public WorkCount answeredBy(String structure) {
        return new WorkCount(rays, testsByKind, nodesVisited, secondaryRays, Map.of(structure, rays));
    }

    /** The rays the camera made: all rays traced but the secondary ones. */
    public long cameraRays() {
        return rays - secondaryRays.values().stream().mapToLong(Long::longValue).sum();
    }

    private static Map<String, Long> sum(Map<String, Long> a, Map<String, Long> b) {
        Map<String, Long> sum = new TreeMap<>(a);
        b.forEach((key, count) -> sum.merge(key, count, Long::sum));
        return sum;
    }

    /** One ray's work in the paper's loop: a test of each of {@code objects}, times {@code rays}. */
    public static WorkCount testsOf(List<IGeometry> objects, long rays) {
        Map<String, Long> tests = new TreeMap<>();
        objects.forEach(object -> tests.merge(object.kind(), 1L, Long::sum));
        return new WorkCount(1, tests, 0).times(rays);
    }

    /** This work done {@code factor} times. */
    public WorkCount times(long factor) {
        return new WorkCount(rays * factor, scaled(testsByKind, factor), nodesVisited * factor,
                scaled(secondaryRays, factor), scaled(answeredBy, factor));
    }

    private static Map<String, Long> scaled(Map<String, Long> counts, long factor) {
        Map<String, Long> scaled = new TreeMap<>();
        counts.forEach((key, count) -> scaled.put(key, count * factor));
        return scaled;
    }

    /** The sum of this and {@code other}. */
    public WorkCount plus(WorkCount other) {
        return new WorkCount(rays + other.rays, sum(testsByKind, other.testsByKind), nodesVisited + other.nodesVisited,
                sum(secondaryRays, other.secondaryRays), sum(answeredBy, other.answeredBy));
    }

    /** Intersection tests of every kind. */
    public long intersectionTests() {
        return testsByKind.values().stream().mapToLong(Long::longValue).sum();
    }

    /** Intersection tests per ray. */
    public double testsPerRay() {
        return rays == 0 ? 0 : (double) intersectionTests() / rays;
    }

    /** Intersection tests of one kind per ray. */
    public double testsPerRay(String kind) {
        return rays == 0 ? 0 : (double) testsByKind.getOrDefault(kind, 0L) / rays;
    }

    /** Bounding-volume nodes visited per ray. */
    public double nodesPerRay() {
        return rays == 0 ? 0 : (double) nodesVisited / rays;
    }
}
