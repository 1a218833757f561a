package rtd.explain;

import rtd.geometry.TestObserver;

/**
 * The test of a solid with a side and two flat caps explained, a cylinder's or a cone's (Part
 * III, "More shapes"): the side's quadratic and each of its roots with its place along the axis,
 * then each cap's plane and the distance from its centre, then the nearest part; the numbers the
 * shape's {@code hit} tells as it computes them. {@link CylinderSteps} and {@link ConeSteps} say
 * what the side's coefficients are.
 */
class SideAndCapsSteps implements TestObserver {

    private static final String[] CAPS = {"first cap (at A)", "second cap (at B)"};
    private static final String[] CENTRES = {"A", "B"};

    private final Text text;
    private final String[] coefficients;

    /** Steps into {@code text} whose side's a, b and c are {@code coefficients}, as formulas. */
    SideAndCapsSteps(Text text, String head, String[] coefficients) {
        this.text = text;
        this.coefficients = coefficients.clone();
        text.hanging(head);
    }

    @Override
    public void side(float t0, float a, float b, float c, float discriminant) {
        text.line("side, from O' = O + t0·R nearest the axis's middle M, t0 = (M − O)·R/(R·R) = " + Numbers.of(t0) + ":");
        text.line("  a·t'² + b·t' + c = 0 with w = O' − A, h the unit axis, and t = t0 + t'");
        text.line("  a = " + coefficients[0] + " = " + Numbers.of(a));
        text.line("  b = " + coefficients[1] + " = " + Numbers.of(b));
        text.line("  c = " + coefficients[2] + " = " + Numbers.of(c));
        text.line("  discriminant b² − 4ac = " + Numbers.of(discriminant)
                + (a == 0 ? ", a = 0: one root, −c/b" : discriminant >= 0 ? " ≥ 0" : " < 0: the ray misses the side"));
    }

    @Override
    public void sideRoot(float t, float along, boolean between) {
        text.line("  root t = t0 + t' = " + Numbers.of(t) + ": s = h·(P − A) = " + Numbers.of(along)
                + (between ? ", between the ends" : ", beyond an end: not on the side"));
    }

    @Override
    public void cap(int end, float t, float fromCentreSquared, float radiusSquared) {
        if (Float.isNaN(t)) {
            text.line(CAPS[end] + ": the ray runs parallel to its plane or meets it behind O");
            return;
        }
        String centre = CENTRES[end];
        text.line(CAPS[end] + ": its plane at t = " + Numbers.of(t) + ", |P − " + centre + "|² = "
                + Numbers.of(fromCentreSquared) + (fromCentreSquared <= radiusSquared ? " ≤ " : " > ") + "r² = "
                + Numbers.of(radiusSquared) + (fromCentreSquared <= radiusSquared ? ": on the cap" : ": beside the cap"));
    }

    @Override
    public void nearestPart(String part, float t) {
        text.line(part.equals("none") ? "no part is hit at t ≥ 0: no hit"
                : "nearest: t = " + Numbers.of(t) + " on the " + part + ": a hit");
    }
}
