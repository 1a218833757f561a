package rtd.scene;

import rtd.image.Rgb;
import rtd.math.Vector3f;

/**
 * A point light (Part II, "Light"): it shines from one point with one colour. A scene with
 * lights is shaded; a scene without is drawn in the paper's flat colours. An area light is a
 * grid of point lights ({@link AreaLight#samples}), each of which names the area light it
 * belongs to; every path that sums point lights draws it unchanged.
 *
 * @param position  where the light is
 * @param intensity its colour and brightness; 1 a channel is full white (255 in the scene file)
 * @param area      the area light this light is a sample of, or null for a light of its own
 */
public record Light(Vector3f position, Rgb intensity, AreaLight area) {

    /** A point light of its own, as the {@code light} statement makes. */
    public Light(Vector3f position, Rgb intensity) {
        this(position, intensity, null);
    }

    /**
     * How far short of the light a shadow ray ends: {@code ε = 1e-4·(1 + max(|x|, |y|, |z|))} of
     * the light's position, the lift off a surface at the ray's other end ({@code rtd.shade.Surface})
     * measured at the light. Without it, a light placed on a surface (a lamp on a ball, on a
     * wall) would shadow what it lights by a rounding error at random: the shadow ray ends on
     * that surface, and its hit there lies a hair nearer or farther than the light.
     */
    public float clearance() {
        return 1e-4f * (1 + Math.max(Math.abs(position.x()), Math.max(Math.abs(position.y()), Math.abs(position.z()))));
    }
}
