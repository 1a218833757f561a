package rtd.shade;

import java.util.Arrays;
import java.util.List;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
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
    /**
     * Whether object {@code index} is patterned, at {@code index + 1}
     * as in {@link #colours}: its colour is found at the hit.
     */
    private final boolean[] patterned;
    private final List<IGeometry> objects;
    private final boolean anyPatterned;

    /** The flat colours of {@code scene}'s objects. */
    public FlatShader(Scene scene) {
        objects = scene.objects();
        colours = new int[objects.size() + 1];
        patterned = new boolean[colours.length];
        colours[0] = scene.ambient().getRGB();
        boolean any = false;
        for (int i = 1; i < colours.length; i++) {
            colours[i] = objects.get(i - 1).color().getRGB();
            patterned[i] = objects.get(i - 1).isPatterned();
            any |= patterned[i];
        }
        anyPatterned = any;
    }

    /**
     * A bundle that missed everything is the background throughout, filled at once: much of the
     * paper's picture is sky, and colouring it ray by ray would be much of its render.
     */
    @Override
    public void rgbAll(RayBundle rays, HitBuffer hits, int count, int[] rgb) {
        if (hits.missedAll()) {
            Arrays.fill(rgb, 0, count, colours[0]);
        } else if (anyPatterned) {
            for (int i = 0; i < count; i++) {
                rgb[i] = rgb(rays, hits, i);
            }
        } else {
            for (int i = 0; i < count; i++) {
                rgb[i] = colours[hits.index(i) + 1];
            }
        }
    }

    /** The object's flat colour; a patterned object's at the hit ({@link Hit#colour}), as the paper's loop finds it. */
    @Override
    public int rgb(RayBundle rays, HitBuffer hits, int i) {
        int at = hits.index(i) + 1;
        if (!patterned[at]) {
            return colours[at];
        }
        Ray ray = rays.ray(i);
        return hits.hit(i, ray, objects).colour(ray.direction()).getRGB();
    }

    @Override
    public Rgb colour(RayBundle rays, HitBuffer hits, int i) {
        return Rgb.of(Color.fromRGB(rgb(rays, hits, i)));
    }
}
