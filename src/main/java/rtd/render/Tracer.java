package rtd.render;

import rtd.math.Ray;
import rtd.scene.Color;

/**
 * Finds the colour one ray sees: the intersection and depth tests of Listing 3.1, lines 3–6.
 *
 * <p>{@link LinearTracer} is the paper's loop over all objects; {@link rtd.accel.BvhTracer}
 * gets the same answer from a bounding volume hierarchy. A tracer counts its work and so is
 * not thread-safe: {@link ParallelRenderer} gives each thread its own.
 */
public interface Tracer {

    /** The colour of the nearest object the ray hits, or the scene's ambient colour. */
    Color trace(Ray ray);

    /**
     * The colours of the bundle's rays, as {@code 0xRRGGBB}, into {@code rgb}. The rays come
     * from a small square of neighbouring pixels; a tracer may use what they share to go
     * faster. By default it traces them one by one.
     */
    default void traceAll(RayBundle rays, int[] rgb) {
        for (int i = 0; i < rays.count(); i++) {
            rgb[i] = trace(rays.ray(i)).getRGB();
        }
    }

    /** The work this tracer has done so far. */
    WorkCount work();
}
