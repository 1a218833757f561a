package rtd.shade;

import java.util.Arrays;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.render.Shader;
import rtd.scene.Scene;

/**
 * The paper's colours (section 3.2.3): a ray takes the flat colour of the object it hits, or
 * the scene's {@code ambient} colour if it hits nothing.
 */
public final class FlatShader implements Shader {

    /**
     * The background's colour at 0, then each object's in file order: the colour of a ray whose
     * nearest object is at place {@code index} (−1: none) is {@code colours[index + 1]}, so that
     * a hit and a miss take the same path, without a branch.
     */
    private final int[] colours;

    /** The flat colours of {@code scene}'s objects. */
    public FlatShader(Scene scene) {
        colours = new int[scene.objects().size() + 1];
        colours[0] = scene.ambient().getRGB();
        for (int i = 1; i < colours.length; i++) {
            colours[i] = scene.objects().get(i - 1).color().getRGB();
        }
    }

    /**
     * A bundle that missed everything is the background throughout, filled at once: much of the
     * paper's picture is sky, and colouring it ray by ray would be much of its render.
     */
    @Override
    public void rgbAll(RayBundle rays, HitBuffer hits, int count, int[] rgb) {
        if (hits.missedAll()) {
            Arrays.fill(rgb, 0, count, colours[0]);
        } else {
            for (int i = 0; i < count; i++) {
                rgb[i] = colours[hits.index(i) + 1];
            }
        }
    }

    @Override
    public int rgb(RayBundle rays, HitBuffer hits, int i) {
        return colours[hits.index(i) + 1];
    }

    @Override
    public Rgb colour(RayBundle rays, HitBuffer hits, int i) {
        return Rgb.of(Color.fromRGB(rgb(rays, hits, i)));
    }
}
