package rtd.render;

import java.util.Map;
import rtd.image.Rgb;

/**
 * Decides the colour a ray sees from what it hit: the paper's flat colours
 * ({@code rtd.shade.FlatShader}), shading with lights ({@code rtd.shade.WhittedShader}), or a
 * debug view. It sits above the hit query: a {@link Tracer} has found the hit already, and a
 * shader that follows secondary rays asks its own tracer for theirs.
 *
 * <p>One per thread, with that thread's tracer: a shader may count its work.
 */
public interface Shader {

    /** The colour, as light (channels from 0 to 1, or beyond), of ray {@code i} of {@code rays}, whose nearest hit is entry {@code i} of {@code hits}. */
    Rgb colour(RayBundle rays, HitBuffer hits, int i);

    /** {@link #colour} as the picture stores it, {@code 0xRRGGBB}: clamped and rounded ({@link Rgb#toColor}). */
    default int rgb(RayBundle rays, HitBuffer hits, int i) {
        return colour(rays, hits, i).toColor().getRGB();
    }

    /**
     * {@link #rgb} of rays {@code 0} to {@code count − 1}, into {@code rgb}. A shader may colour
     * a bundle whose rays all missed ({@link HitBuffer#missedAll}) at once.
     */
    default void rgbAll(RayBundle rays, HitBuffer hits, int count, int[] rgb) {
        for (int i = 0; i < count; i++) {
            rgb[i] = rgb(rays, hits, i);
        }
    }

    /** The rays this shader followed beyond the camera's, by kind ("shadow", "reflected", ...); none by default. */
    default Map<String, Long> secondaryRays() {
        return Map.of();
    }
}
