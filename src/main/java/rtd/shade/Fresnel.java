package rtd.shade;

/**
 * How much of the light a surface that both reflects and lets light through reflects
 * (Part II, "Light", step 6): Schlick's approximation of Fresnel's equations. Glass reflects
 * little when seen face on, and more and more towards grazing angles.
 */
final class Fresnel {

    private Fresnel() {
    }

    /**
     * {@code R = r0 + (1 − r0)(1 − cos)^5} with {@code r0 = ((n1 − n2)/(n1 + n2))²}; cos is
     * the angle of incidence's, or, going into a thinner medium, the refracted ray's; under
     * total internal reflection R = 1.
     */
    static float schlick(Surface surface) {
        Snell snell = Snell.at(surface);
        float cos = snell.cosIncidence();
        if (snell.from() > snell.to()) {
            if (snell.totalInternalReflection()) {
                return 1;
            }
            cos = snell.cosTransmitted();
        }
        float r0 = (snell.from() - snell.to()) / (snell.from() + snell.to());
        r0 = r0 * r0;
        return r0 + (1 - r0) * (float) Math.pow(1 - cos, 5);
    }
}
