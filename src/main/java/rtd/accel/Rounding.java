package rtd.accel;

/**
 * How far a float intersection test may report a hit beside its object's box, as the ray runs
 * a distance {@code L = t·|R|} to the hit: at most {@code linear·L + min(ROUNDING_CONE·L,
 * quadratic·L²)} ({@link KnownShapes#rounding}). The engine grows its boxes by that much, and no
 * more, so that it finds every hit the test reports and visits few boxes beside.
 *
 * @param linear    the share of L that rounding may add in any case
 * @param quadratic the factor of L² that bounds it when that is less than the cone
 */
record Rounding(float linear, float quadratic) {

    /** The widest cone, for a shape that says nothing of its rounding. */
    static final Rounding WIDEST = new Rounding(KnownShapes.ROUNDING_CONE, 0);

    /** Rounding that grows only in proportion to the distance, by {@code linear}. */
    static Rounding linear(float linear) {
        return new Rounding(linear, 0);
    }
}
