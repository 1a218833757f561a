package rtd.explain;

import rtd.geometry.Cylinder;

/**
 * The test of a cylinder explained (Part III, "More shapes"): the numbers {@link Cylinder#hit}
 * tells as it computes them, its side's quadratic written as that method's equations are.
 */
final class CylinderSteps extends SideAndCapsSteps {

    private static final String[] SIDE = {"R·R − (h·R)²", "2·(w·R − (h·w)(h·R))", "w·w − (h·w)² − r²"};

    CylinderSteps(Text text, String head, Cylinder cylinder) {
        super(text, head + "cylinder: A = " + Numbers.of(cylinder.first()) + ", B = " + Numbers.of(cylinder.second())
                + ", r = " + Numbers.of(cylinder.radius()), SIDE);
    }
}
