package rtd.render;

import java.util.Map;
import rtd.image.Rgb;

/**
 * The colour a ray sees from what a {@link Tracer} found it hits: the paper's flat colours, shading with lights, or a
 * debug view. A shader that follows secondary rays asks its thread's tracer for theirs, and may count its work.
 */
public interface Shader {

    /** Ray {@code i}'s colour as light (channels from 0 to 1, or beyond), its nearest hit in {@code hits}. */
    Rgb colour(RayBundle rays, HitBuffer hits, int i);

    /** {@link #colour} as the picture stores it, {@code 0xRRGGBB}: clamped and rounded ({@link Rgb#toColor}). */
    default int rgb(RayBundle rays, HitBuffer hits, int i) {
        return colour(rays, hits, i).toColor().getRGB();
    }

    /** {@link #rgb} of rays 0 to {@code count − 1}; may colour at once a bundle that {@link HitBuffer#missedAll}. */
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
