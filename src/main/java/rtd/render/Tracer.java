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

    /** The work this tracer has done so far. */
    WorkCount work();
}
