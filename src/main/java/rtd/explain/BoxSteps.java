package rtd.explain;

import rtd.geometry.Box;
import rtd.math.Ray;

/**
 * The slab test of a box explained: along each axis the interval of t in which the ray is
 * between the box's two faces, then their overlap; the float operations of {@link Box#intersect}.
 */
final class BoxSteps {

    private static final String[] AXES = {"x", "y", "z"};

    private BoxSteps() {
    }

    /** Writes the test into {@code text} and returns its t (NaN: no hit). */
    static float explain(Text text, String head, Box box, Ray ray) {
        float[] o = {ray.origin().x(), ray.origin().y(), ray.origin().z()};
        float[] d = {ray.direction().x(), ray.direction().y(), ray.direction().z()};
        float[] lo = {box.min().x(), box.min().y(), box.min().z()};
        float[] hi = {box.max().x(), box.max().y(), box.max().z()};
        text.hanging(head + "box: min = " + Numbers.of(box.min()) + ", max = " + Numbers.of(box.max()));
        float enter = Float.NEGATIVE_INFINITY;
        float exit = Float.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            if (d[k] == 0) {
                boolean outside = o[k] < lo[k] || o[k] > hi[k];
                text.line(AXES[k] + ": R" + AXES[k] + " = 0, the ray runs parallel to the slab and is "
                        + (outside ? "outside it: no hit" : "inside it everywhere"));
                if (outside) {
                    return Float.NaN;
                }
                continue;
            }
            float t0 = (lo[k] - o[k]) / d[k];
            float t1 = (hi[k] - o[k]) / d[k];
            text.line(AXES[k] + ": t from (min − O)/R = " + Numbers.of(t0) + " to (max − O)/R = " + Numbers.of(t1));
            enter = Math.max(enter, Math.min(t0, t1));
            exit = Math.min(exit, Math.max(t0, t1));
        }
        text.line("in all three slabs: t from " + Numbers.of(enter) + " (enter, the largest start) to " + Numbers.of(exit)
                + " (exit, the smallest end)");
        if (enter > exit || exit < 0) {
            text.line(enter > exit ? "enter > exit: the intervals do not overlap, no hit" : "exit < 0: the box lies behind O, no hit");
            return Float.NaN;
        }
        float t = enter >= 0 ? enter : exit;
        if (!Float.isFinite(t)) { // as Box.intersect: a direction so short that t overflows
            text.line("t = " + Numbers.of(t) + " is not finite: the ray's direction is too short to reach the box, no hit");
            return Float.NaN;
        }
        text.line(enter >= 0 ? "t = enter = " + Numbers.of(t) + ": a hit" : "enter < 0: O is inside, t = exit = " + Numbers.of(t) + ": a hit");
        return t;
    }
}
