package rtd.shade;

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

    private final int[] colours;
    private final int background;

    /** The flat colours of {@code scene}'s objects. */
    public FlatShader(Scene scene) {
        colours = new int[scene.objects().size()];
        for (int i = 0; i < colours.length; i++) {
            colours[i] = scene.objects().get(i).color().getRGB();
        }
        background = scene.ambient().getRGB();
    }

    @Override
    public int rgb(RayBundle rays, HitBuffer hits, int i) {
        int object = hits.index(i);
        return object < 0 ? background : colours[object];
    }

    @Override
    public Rgb colour(RayBundle rays, HitBuffer hits, int i) {
        return Rgb.of(Color.fromRGB(rgb(rays, hits, i)));
    }
}
