package rtd.accel;

import java.util.Arrays;

/**
 * The last few objects of the tree that blocked a shadow ray ({@link BvhTracer#blocked}), to be
 * tried first on the next one. Neighbouring points in a shadow are mostly shadowed by the same
 * object, so one intersection test often answers a question that a walk down the tree answers
 * only after dozens of boxes. POV-Ray's light buffer rests on the same observation.
 *
 * <p>Whether a shadow ray is blocked does not depend on which object blocks it, so trying these
 * first changes the work done, never the answer or the picture. Each tracer has its own, so it
 * needs no locking; which objects it remembers depends on the pixels its thread drew, which is
 * why it may only ever decide the order of the tests.
 *
 * <p>Four places, because a point is lit by several lights, each with its own blockers: one
 * place would be taken by the other light's blocker at every other ray.
 */
final class RecentBlockers {

    private static final int SIZE = 4;
    /** Places in leaf order ({@link LeafObjects}); −1 where none is remembered yet. */
    private final int[] places = new int[SIZE];
    /** The place to overwrite next: the oldest. */
    private int next;

    RecentBlockers() {
        Arrays.fill(places, -1);
    }

    /** The places to try first, −1 for an empty one; not to be changed. */
    int[] places() {
        return places;
    }

    /** Remembers the object at {@code place} in leaf order, in place of the oldest, unless it is remembered already. */
    void remember(int place) {
        for (int known : places) {
            if (known == place) {
                return;
            }
        }
        places[next] = place;
        next = (next + 1) % SIZE;
    }
}
