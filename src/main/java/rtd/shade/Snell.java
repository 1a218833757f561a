package rtd.shade;

/**
 * Snell's law at a surface (Part II, "Light", step 5): the ratio {@code n = n1/n2} of the
 * indices of refraction on the ray's side and beyond, the cosines of the angles of incidence
 * and of the refracted ray, and whether the light is totally reflected instead
 * ({@code sin²θt = n²(1 − cos²θi) > 1}); and how much of the light such a surface reflects
 * (Part II, "Light", step 6). Air outside every object; nested objects are not modelled.
 *
 * @param from           n1, the index on the ray's side
 * @param to             n2, the index beyond the surface
 * @param cosIncidence   {@code cos θi = E·N}
 * @param sin2Transmitted {@code sin²θt}
 */
public record Snell(float from, float to, float cosIncidence, float sin2Transmitted) {

    /** The law at {@code surface}: entering the object from air, or leaving it into air. */
    static Snell at(Surface surface) {
        float ior = surface.material().ior();
        float from = surface.inside() ? ior : 1;
        float to = surface.inside() ? 1 : ior;
        float ratio = from / to;
        float cos = surface.eye().dot(surface.normal());
        // 1 − cos² is never negative; rounding can make cos a hair above 1 face on, and a large ior's
        // n² would blow that hair up into a cos θt far above 1 (and a reflectance far below 0)
        return new Snell(from, to, cos, ratio * ratio * Math.max(0, 1 - cos * cos));
    }

    /** {@code n1 / n2}. */
    public float ratio() {
        return from / to;
    }

    /** Past the critical angle: no light passes, all is reflected inside. */
    public boolean totalInternalReflection() {
        return sin2Transmitted > 1;
    }

    /** {@code cos θt = √(1 − sin²θt)}. */
    public float cosTransmitted() {
        return (float) Math.sqrt(1 - sin2Transmitted);
    }

    /**
     * Schlick's approximation of Fresnel's equations, the share of the light reflected:
     * {@code R = r0 + (1 − r0)(1 − cos)^5} with {@code r0 = ((n1 − n2)/(n1 + n2))²}; cos is the
     * angle of incidence's, or, going into a thinner medium, the refracted ray's; under total
     * internal reflection R = 1. Glass reflects little face on, and more towards grazing angles.
     */
    float reflectance() {
        float cos = cosIncidence;
        if (from > to) {
            if (totalInternalReflection()) {
                return 1;
            }
            cos = cosTransmitted();
        }
        float r0 = (from - to) / (from + to);
        r0 = r0 * r0;
        return r0 + (1 - r0) * (float) Math.pow(1 - cos, 5);
    }
}
