package rtd.explain;

import rtd.geometry.Plane;
import rtd.geometry.TestObserver;

/** The intersection test of a plane explained: the numbers {@link Plane#hit} tells as it computes them. */
final class PlaneSteps implements TestObserver {

    private final Text text;

    PlaneSteps(Text text, String head, Plane plane) {
        this.text = text;
        text.hanging(head + "plane: Q = " + Numbers.of(plane.point()) + ", n = " + Numbers.of(plane.normal()));
    }

    @Override
    public void plane(float facing, float along, float t) {
        text.line("R·n = " + Numbers.of(facing));
        if (facing == 0) {
            text.line("R·n = 0: the ray runs parallel to the plane, no hit");
            return;
        }
        String verdict = t == Float.POSITIVE_INFINITY ? ": the ray runs so nearly parallel that it never meets it, no hit"
                : t >= 0 ? " ≥ 0: a hit" : ": the plane lies behind O, no hit";
        text.line("t = ((Q − O)·n) / (R·n) = " + Numbers.of(along) + " / " + Numbers.of(facing) + " = " + Numbers.of(t) + verdict);
    }
}
