package rtd.geometry;

/**
 * How a surface takes light: the finish of the shading model (Part II, "Light"; the model of
 * <i>The Ray Tracer Challenge</i>). A scene names finishes with {@code material:} statements and
 * objects use them in their last group; an object that names none has {@link #DEFAULT}.
 *
 * <p>A scene without lights is drawn flat, as in the paper, and then no finish has any effect.
 *
 * @param ambient      the share of each light's colour every point gets, lit or not
 * @param diffuse      the share of Lambert's diffuse reflection, {@code N·L}
 * @param specular     the strength of Phong's highlight
 * @param shininess    how small and sharp the highlight is (its exponent)
 * @param reflective   how much of a mirror image the surface shows, 0 to 1
 * @param transparency how much of what lies behind shows through, 0 to 1
 * @param ior          the index of refraction, at least 1 (1 is air, 1.5 glass)
 */
public record Material(float ambient, float diffuse, float specular, float shininess, float reflective,
        float transparency, float ior) {

    /** The finish of an object that names none. */
    public static final Material DEFAULT = new Material(0.1f, 0.9f, 0.9f, 200f, 0f, 0f, 1f);
}
