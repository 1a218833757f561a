package rtd.shade;

import rtd.geometry.Material;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.scene.Light;

/**
 * The light one point light gives a point of a surface: the Phong reflection model as <i>The
 * Ray Tracer Challenge</i> uses it (Part II, "Light", step 3). Three terms, each a share of
 * the light's colour:
 * <ul>
 * <li>ambient: {@code ambient · c ⊙ I}, light that is everywhere, lit or in shadow;</li>
 * <li>diffuse (Lambert): {@code diffuse · c ⊙ I · (N·L)}, brightest where the surface faces
 *     the light;</li>
 * <li>specular (Phong): {@code specular · I · (Rl·E)^shininess}, the highlight where the
 *     light's reflection {@code Rl = 2(N·L)N − L} points at the eye.</li>
 * </ul>
 */
public final class Lighting {

    private Lighting() {
    }

    /**
     * The light {@code light} gives the point {@code point} (the hit point lifted off the
     * surface, "over") of a surface of colour {@code colour} and finish {@code material}, seen
     * from the direction {@code eye} (unit, towards the viewer), with unit normal {@code normal};
     * a point in {@code shadow} gets the ambient term only.
     */
    public static Rgb of(Material material, Rgb colour, Light light, Vector3f point, Vector3f eye, Vector3f normal,
            boolean shadow) {
        return terms(material, colour, light, point, eye, normal, shadow).sum();
    }

    /** {@link #of}'s three terms, each as it computes them; a term the light does not give is black. */
    public static LightTerms terms(Material material, Rgb colour, Light light, Vector3f point, Vector3f eye,
            Vector3f normal, boolean shadow) {
        Rgb effective = colour.times(light.intensity());                     // c ⊙ I
        Rgb ambient = effective.times(material.ambient());
        Vector3f toLight = light.position().subtract(point).normalize();     // L
        float lightFacing = toLight.dot(normal);                             // N·L
        if (shadow || !(lightFacing > 0)) { // also a light at the point itself: no direction, NaN
            // the light is behind the surface, or something stands in its way
            return new LightTerms(ambient, Rgb.BLACK, Rgb.BLACK, lightFacing, Float.NaN);
        }
        Rgb diffuse = effective.times(material.diffuse() * lightFacing);
        Vector3f reflected = normal.multiply(2 * lightFacing).subtract(toLight); // Rl = 2(N·L)N − L
        float reflectionToEye = reflected.dot(eye);                          // Rl·E
        if (reflectionToEye <= 0) {
            // the highlight points away
            return new LightTerms(ambient, diffuse, Rgb.BLACK, lightFacing, reflectionToEye);
        }
        float highlight = (float) Math.pow(reflectionToEye, material.shininess());
        return new LightTerms(ambient, diffuse, light.intensity().times(material.specular() * highlight), lightFacing,
                reflectionToEye);
    }
}
