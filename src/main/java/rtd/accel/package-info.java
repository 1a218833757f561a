/**
 * Faster ways to the paper's hits, bit for bit: a bounding volume hierarchy
 * ({@link rtd.accel.Bvh}), a grid on the image for the camera's rays ({@link rtd.accel.ViewGrid})
 * a grid seen from each light for shadow rays ({@link rtd.accel.LightGrids}) and a grid seen from
 * the eye's mirror image for the rays a flat mirror reflects ({@link rtd.accel.MirrorGrids}). Not
 * in the paper:
 * each answers the paper's depth test (Listing 4.3) for many objects without testing them all, and
 * tests hold each to the loop of {@code rtd.scene.Scene}. Implements {@code rtd.render.Tracer}.
 */
package rtd.accel;
