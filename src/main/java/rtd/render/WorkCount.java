package rtd.render;

/**
 * How much work tracing took: rays, intersection tests, and bounding-volume nodes visited.
 * {@code --stats} prints it per ray, so a student sees N tests per ray without the hierarchy
 * and about log N with it.
 */
public record WorkCount(long rays, long intersectionTests, long nodesVisited) {

    /** No work at all. */
    public static final WorkCount NONE = new WorkCount(0, 0, 0);

    /** The sum of this and {@code other}. */
    public WorkCount plus(WorkCount other) {
        return new WorkCount(rays + other.rays, intersectionTests + other.intersectionTests,
                nodesVisited + other.nodesVisited);
    }

    /** Intersection tests per ray. */
    public double testsPerRay() {
        return rays == 0 ? 0 : (double) intersectionTests / rays;
    }

    /** Bounding-volume nodes visited per ray. */
    public double nodesPerRay() {
        return rays == 0 ? 0 : (double) nodesVisited / rays;
    }
}
