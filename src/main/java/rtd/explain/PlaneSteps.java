package rtd.explain;

import rtd.geometry.Plane;
import rtd.math.Ray;

/** The intersection test of a plane explained: the float operations of {@link Plane#intersect}. */
final class PlaneSteps {

    private PlaneSteps() {
    }

    /** Writes the test into {@code text} and returns its t (NaN: no hit). */
    static float explain(Text text, String head, Plane plane, Ray ray) {
        float facing = ray.direction().dot(plane.normal());
        float along = plane.point().subtract(ray.origin()).dot(plane.normal());
        float t = along / facing;
        text.hanging(head + "plane: Q = " + Numbers.of(plane.point()) + ", n = " + Numbers.of(plane.normal()));
        text.line("R·n = " + Numbers.of(facing));
        if (facing == 0) {
            text.line("R·n = 0: the ray runs parallel to the plane, no hit");
            return Float.NaN;
        }
        String verdict = t == Float.POSITIVE_INFINITY ? ": the ray runs so nearly parallel that it never meets it, no hit"
                : t >= 0 ? " ≥ 0: a hit" : ": the plane lies behind O, no hit";
        text.line("t = ((Q − O)·n) / (R·n) = " + Numbers.of(along) + " / " + Numbers.of(facing) + " = " + Numbers.of(t) + verdict);
        return t >= 0 && t < Float.POSITIVE_INFINITY ? t : Float.NaN; // Plane.hit's verdict
    }
}
