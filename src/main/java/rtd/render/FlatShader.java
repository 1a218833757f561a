package rtd.render;

import rtd.image.Color;
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
        colours = scene.objects().stream().map(object -> object.color()).mapToInt(Color::getRGB).toArray();
        background = scene.ambient().getRGB();
    }

    @Override
    public int rgb(RayBundle rays, HitBuffer hits, int i) {
        int object = hits.index(i);
        return object < 0 ? background : colours[object];
    }
}
