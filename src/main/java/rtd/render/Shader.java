package rtd.render;

/**
 * Decides the colour a ray sees from what it hit: flat colours as in the paper
 * ({@link FlatShader}), and, above the same hit query, shading with lights or a debug view.
 */
public interface Shader {

    /** The colour, as {@code 0xRRGGBB}, of ray {@code i} of {@code rays}, whose nearest hit is entry {@code i} of {@code hits}. */
    int rgb(RayBundle rays, HitBuffer hits, int i);
}
