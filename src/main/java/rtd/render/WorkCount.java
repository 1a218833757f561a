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
 */
public record WorkCount(long rays, Map<String, Long> testsByKind, long nodesVisited) {

    /** No work at all. */
    public static final WorkCount NONE = new WorkCount(0, Map.of(), 0);

    /** Keeps an unmodifiable, sorted copy of the counts. */
    public WorkCount {
        testsByKind = Collections.unmodifiableMap(new TreeMap<>(testsByKind));
    }

    /** One ray's work in the paper's loop: a test of each of {@code objects}, times {@code rays}. */
    public static WorkCount testsOf(List<IGeometry> objects, long rays) {
        Map<String, Long> tests = new TreeMap<>();
        for (IGeometry object : objects) {
            tests.put(object.kind(), tests.getOrDefault(object.kind(), 0L) + 1);
        }
        return new WorkCount(1, tests, 0).times(rays);
    }

    /** This work done {@code factor} times. */
    public WorkCount times(long factor) {
        Map<String, Long> tests = new TreeMap<>();
        for (Map.Entry<String, Long> kind : testsByKind.entrySet()) {
            tests.put(kind.getKey(), kind.getValue() * factor);
        }
        return new WorkCount(rays * factor, tests, nodesVisited * factor);
    }

    /** The sum of this and {@code other}. */
    public WorkCount plus(WorkCount other) {
        Map<String, Long> tests = new TreeMap<>(testsByKind);
        for (Map.Entry<String, Long> kind : other.testsByKind.entrySet()) {
            tests.put(kind.getKey(), tests.getOrDefault(kind.getKey(), 0L) + kind.getValue());
        }
        return new WorkCount(rays + other.rays, tests, nodesVisited + other.nodesVisited);
    }

    /** Intersection tests of every kind. */
    public long intersectionTests() {
        long sum = 0;
        for (long tests : testsByKind.values()) {
            sum += tests;
        }
        return sum;
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
