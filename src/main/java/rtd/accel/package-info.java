/**
 * Faster ways to the paper's hits, bit for bit: a bounding volume hierarchy
 * ({@link rtd.accel.Bvh}) for any ray, a grid on the image for the camera's rays
 * ({@link rtd.accel.ViewGrid}), and a grid seen from each light for shadow rays
 * ({@link rtd.accel.LightGrids}). Not in the paper: each answers the paper's depth test
 * (Listing 4.3) for many objects without testing them all, by running each shape's own test on
 * the objects a ray may hit, and tests hold each to the loop of {@code rtd.scene.Scene}. A shape
 * the engine does not know is tested through its own test and box only. The rest of rtd reaches
 * the engine through {@link rtd.accel.Accelerator} alone, which chooses and builds the structures
 * for {@code --accel}; they answer through {@code rtd.render.Tracer}.
 */
package rtd.accel;
