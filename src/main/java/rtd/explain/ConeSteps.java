package rtd.explain;

import rtd.geometry.Cone;

/**
 * The test of a cone explained (Part III, "More shapes"): the numbers {@link Cone#hit} tells as
 * it computes them, its side's quadratic written as that method's equations are, with the slope
 * {@code k = (r2 − r1)/|B − A|} and {@code g = r1 + k·(h·w)}, the side's radius level with O.
 */
final class ConeSteps extends SideAndCapsSteps {

    private static final String[] SIDE = {"R·R − (1 + k²)(h·R)²", "2·(w·R − (h·w)(h·R) − k·g·(h·R))",
        "w·w − (h·w)² − g²"};

    ConeSteps(Text text, String head, Cone cone) {
        super(text, head + "cone: A = " + Numbers.of(cone.first()) + ", r1 = " + Numbers.of(cone.firstRadius()) + ", B = "
                + Numbers.of(cone.second()) + ", r2 = " + Numbers.of(cone.secondRadius()) + ", k = (r2 − r1)/|B − A|, g = r1 + k·(h·w)",
                SIDE);
    }
}
