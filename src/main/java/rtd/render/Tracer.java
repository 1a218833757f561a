package rtd.render;

import rtd.geometry.Hit;
import rtd.math.Ray;

/**
 * Answers "what does this ray hit?" for any ray: the intersection and depth tests of Listing 3.1, lines 3–5; a
 * {@link Shader} decides the colour (line 6). {@link LinearTracer} is the paper's loop over all objects; rtd.accel's
 * tracers get the same hits from a bounding volume hierarchy and grids. A tracer counts its work, so it is not
 * thread-safe: {@link ParallelRenderer} gives each thread its own.
 */
public interface Tracer {

    /** The nearest hit of the ray, or {@code null} if it hits nothing. */
    Hit nearestHit(Ray ray);

    /**
     * The nearest hits of the bundle's rays, and each one's count of intersection tests, into {@code hits}; the rays
     * of neighbouring pixels, whose likeness a tracer may use. By default one by one.
     */
    default void traceAll(RayBundle rays, HitBuffer hits) {
        for (int i = 0; i < rays.count(); i++) {
            long before = testsRun();
            hits.set(i, nearestHit(rays.ray(i)));
            hits.setTests(i, testsRun() - before);
        }
    }

    /**
     * Whether the tracer can answer the bundle's rays (maybe a run of squares) at once, into {@code hits}: if it can
     * tell that none hits anything, they count as traced with no test ({@link HitBuffer#setMisses}); if their hits
     * were found before the render (an image of hits), as {@link #traceAll} reads them. False, with nothing traced,
     * if some ray may hit or the tracer cannot tell, as by default.
     */
    default boolean traceAtOnce(RayBundle rays, HitBuffer hits) {
        return false;
    }

    /** The intersection tests run so far, as {@link #work} counts them; faster ({@code --view cost} asks per ray). */
    default long testsRun() {
        return work().intersectionTests();
    }

    /**
     * A shadow ray's question: whether the ray hits an object at {@code |P − O| < distance}, as {@code nearestHit}
     * would say; a tracer may answer at the first such hit.
     */
    default boolean blocked(Ray ray, float distance) {
        Hit hit = nearestHit(ray);
        return hit != null && hit.distance() < distance;
    }

    WorkCount work();
}
