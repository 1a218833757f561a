/**
 * Rendering on all cores: a {@link rtd.render.Tracer} finds hits (Listing 3.1, lines 3 to 5), a
 * {@link rtd.render.Shader} turns them into colours (line 6), {@link rtd.render.ParallelRenderer} runs Listing 4.2 on
 * bands of rows. Depends on {@code rtd.scene} and below; {@code rtd.accel} and {@code rtd.shade} implement it.
 */
package rtd.render;
