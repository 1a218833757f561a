package rtd.shade;

import rtd.image.Rgb;

/**
 * The three terms of the Phong model that one light gives a point (Part II, "Light", step 3):
 * what {@link Lighting#of} adds up, kept apart so that {@code --explain} can show each.
 *
 * @param ambient  {@code ambient · c ⊙ I}, given lit or in shadow
 * @param diffuse  {@code diffuse · c ⊙ I · (N·L)}, black if the light is shadowed or behind the surface
 * @param specular {@code specular · I · (Rl·E)^shininess}, black where the highlight points away from the eye
 * @param lightFacing {@code N·L}, the cosine between the normal and the direction to the light
 * @param reflectionToEye {@code Rl·E}, NaN where it was not needed (no diffuse light)
 */
public record LightTerms(Rgb ambient, Rgb diffuse, Rgb specular, float lightFacing, float reflectionToEye) {

    /** The light the point gets: {@code ambient + diffuse + specular}, summed in that order. */
    public Rgb sum() {
        return ambient.plus(diffuse).plus(specular); // adding black changes no bit of a sum
    }
}
