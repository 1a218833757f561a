package rtd.explain;

import rtd.geometry.Box;
import rtd.geometry.TestObserver;

/**
 * The slab test of a box explained: along each axis the interval of t in which the ray is
 * between the box's two faces, near to far, then their overlap; the numbers {@link Box#hit}
 * tells as it computes them.
 */
final class BoxSteps implements TestObserver {

    private static final String[] AXES = {"x", "y", "z"};

    private final Text text;
    private float enter = Float.NaN;
    private float exit = Float.NaN;

    BoxSteps(Text text, String head, Box box) {
        this.text = text;
        text.hanging(head + "box: min = " + Numbers.of(box.min()) + ", max = " + Numbers.of(box.max()));
    }

    @Override
    public void parallelSlab(int axis, boolean outside) {
        text.line(AXES[axis] + ": R" + AXES[axis] + " = 0, the ray runs parallel to the slab and is "
                + (outside ? "outside it: no hit" : "inside it everywhere"));
    }

    @Override
    public void slab(int axis, float t0, float t1) {
        String low = "(min − O)/R = ";
        String high = "(max − O)/R = ";
        text.line(AXES[axis] + ": t from " + (t0 <= t1 ? low + Numbers.of(t0) + " to " + high + Numbers.of(t1)
                : high + Numbers.of(t1) + " to " + low + Numbers.of(t0)));
    }

    @Override
    public void slabs(float enter, float exit) {
        this.enter = enter;
        this.exit = exit;
        text.line("in all three slabs: t from " + Numbers.of(enter) + " (enter, the largest start) to " + Numbers.of(exit)
                + " (exit, the smallest end)");
    }

    /** The verdict on the test's answer {@code t}, once the slabs are known. */
    void verdict(float t) {
        if (Float.isNaN(enter)) {
            return; // a parallel slab the ray is outside of: already said
        }
        if (enter > exit || exit < 0) {
            text.line(enter > exit ? "enter > exit: the intervals do not overlap, no hit" : "exit < 0: the box lies behind O, no hit");
        } else if (!(t >= 0)) {
            text.line("t = " + Numbers.of(enter >= 0 ? enter : exit)
                    + " is not finite: the ray's direction is too short to reach the box, no hit");
        } else {
            text.line(enter >= 0 ? "t = enter = " + Numbers.of(t) + ": a hit" : "enter < 0: O is inside, t = exit = " + Numbers.of(t) + ": a hit");
        }
    }
}
