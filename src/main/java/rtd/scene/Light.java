package rtd.scene;

import rtd.image.Rgb;
import rtd.math.Vector3f;

/**
 * A point light (Part II, "Light"): it shines from one point with one colour. A scene with
 * lights is shaded; a scene without is drawn in the paper's flat colours.
 *
 * @param position  where the light is
 * @param intensity its colour and brightness; 1 a channel is full white (255 in the scene file)
 */
public record Light(Vector3f position, Rgb intensity) {
}
