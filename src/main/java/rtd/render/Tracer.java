package rtd.render;

import rtd.geometry.Hit;
import rtd.math.Ray;

/**
 * Answers "what does this ray hit?": the intersection and depth tests of Listing 3.1, lines
 * 3–5, for any ray, a camera's or not. It finds hits, not colours; a {@link Shader} decides the
 * colour (line 6).
 *
 * <p>{@link LinearTracer} is the paper's loop over all objects; {@code rtd.accel.BvhTracer}
 * gets the same hits from a bounding volume hierarchy, {@code rtd.accel.ViewGridTracer} for the
 * camera's rays from a grid on the image, and {@code rtd.accel.LightGridTracer} for shadow rays
 * from a grid seen from each light. A tracer counts its work and so is not
 * thread-safe: {@link ParallelRenderer} gives each thread its own.
 */
public interface Tracer {

    /** The nearest hit of the ray, or {@code null} if it hits nothing. */
    Hit nearestHit(Ray ray);

    /**
     * The nearest hits of the bundle's rays into {@code hits}. The rays come from a small square
     * of neighbouring pixels; a tracer may use what they share to go faster. By default it
     * traces them one by one. Each ray's count of intersection tests goes into {@code hits} too.
     */
    default void traceAll(RayBundle rays, HitBuffer hits) {
        for (int i = 0; i < rays.count(); i++) {
            long before = testsRun();
            hits.set(i, nearestHit(rays.ray(i)));
            hits.setTests(i, testsRun() - before);
        }
    }

    /**
     * Whether the tracer can tell at once, without following them one by one, that none of the
     * bundle's rays hits anything ({@link HitBuffer#setMisses}): then they count as traced, with
     * no intersection test, their answer is in {@code hits}, and the answer is true. False, with
     * nothing traced, if some ray may hit or if the tracer cannot tell; by default it cannot. The bundle may be larger than a square:
     * {@link ParallelRenderer} asks this of a run of squares before it traces them.
     */
    default boolean traceAtOnce(RayBundle rays, HitBuffer hits) {
        return false;
    }

    /**
     * The intersection tests this tracer has run so far: {@link #work}'s, which a tracer may
     * count faster ({@code --view cost} asks before and after every ray).
     */
    default long testsRun() {
        return work().intersectionTests();
    }

    /**
     * Whether the ray hits any object nearer than {@code distance} ({@code |P − O| < distance}):
     * the question of a shadow ray. The answer is the same as {@code nearestHit}'s distance
     * compared with {@code distance}; a tracer may find it sooner, at the first such hit.
     */
    default boolean blocked(Ray ray, float distance) {
        Hit hit = nearestHit(ray);
        return hit != null && hit.distance() < distance;
    }

    WorkCount work();
}
