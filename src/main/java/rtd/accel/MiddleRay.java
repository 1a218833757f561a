package rtd.accel;

import rtd.render.RayBundle;

/**
 * The middle ray of a square's {@link Beam}, and the slab test of boxes grown so that the
 * middle ray's test answers for every ray of the beam ({@link #grownEntry}): what the
 * {@link BeamTracer} tests each box of its walk with, and the entry into a leaf's objects'
 * boxes ({@link #objectsEntry}). Aimed anew at each square ({@link #aim});
 * one per tracer, so that aiming makes no garbage. Not in the paper.
 *
 * <p>Rays from origins within C ± h, with directions within D ± s, form a beam: at any t, every
 * ray's point lies within the middle ray's point C + t·D grown by h + t·s. So a ray passes
 * through a box at some t only if the middle ray passes through the box grown by h + t·s, and
 * t·s may be taken at any t the rays cannot be in the box beyond: the exit of the middle ray from
 * the parent's grown box, which holds the child. One walk down the tree with the middle ray
 * and grown boxes visits every box that any ray of the square enters, and the middle ray's entry
 * into a grown box is a t before which no ray of the square enters that box. The boxes grow a
 * little more (a millionth of the numbers involved, a hundred-thousandth of t·s) than that, so
 * that rounding can never make the beam miss a box that one of its rays enters, and by the
 * rounding margin of the objects' tests, as for one ray ({@link BoxGrowth}).
 */
final class MiddleRay {

    private static final float ROUNDING = 1e-6f;
    /** The share by which the rays' spread grows a box beyond {@code t·spread}, against rounding in the t it is taken at. */
    private static final float FAN_ROUNDING = 1e-5f;
    private static final float MISS = NearestHit.MISS;

    private final Bvh bvh;
    /** The rays' bounds, which {@link #aim} finds first. */
    private final Beam beam;
    /** The centre of the box around the rays' origins (C), which {@link BeamTracer} reads too. */
    final float[] centre = new float[3];
    /** The half size of the box around the rays' origins (h), which {@link BeamTracer} reads too. */
    final float[] half = new float[3];
    /** 1 / D, per axis. */
    private final float[] inverse = new float[3];
    /**
     * Per axis, how much to grow every box for this beam, before the objects' rounding: the
     * half size and the allowance for rounding, taken for the largest numbers of the tree (its
     * root's box holds every box), so that a box's own numbers need not be looked at.
     */
    private final float[] pad = new float[3];
    /** Per axis, whether the rays do not move along it (1 / direction is infinite). */
    private final boolean[] still = new boolean[3];
    /** Per axis, how far any ray's direction is from the middle ray's ({@link Beam#spread}), with a margin for rounding. */
    private final float[] fan = new float[3];
    /** The shortest and longest |D| of the rays: the first bounds how far (in t) they reach, the second how far they run. */
    float shortest;
    float longest;
    /**
     * The exit of the grown box of the last {@link #grownEntry}: a second answer of that call,
     * which {@link BeamTracer}'s walk reads right after it as the t its children grow at.
     */
    float exit;

    /** The middle ray of {@code beam}'s rays, for boxes of {@code bvh}. */
    MiddleRay(Bvh bvh, Beam beam) {
        this.bvh = bvh;
        this.beam = beam;
    }

    /** Aims at the beam of the bundle's rays; false if they are too unlike for a beam ({@link Beam#aimAt}), or it is too large for float. */
    boolean aim(RayBundle bundle) {
        if (!beam.aimAt(bundle)) {
            return false;
        }
        float[] lowest = beam.lowest;
        float[] highest = beam.highest;
        for (int k = 0; k < 3; k++) {
            centre[k] = (lowest[k] + highest[k]) / 2;
            half[k] = (highest[k] - lowest[k]) / 2 + ROUNDING * (Math.abs(lowest[k]) + Math.abs(highest[k]));
            if (!Float.isFinite(centre[k]) || !Float.isFinite(half[k])) {
                return false;
            }
        }
        inverse[0] = 1f / beam.dx;
        inverse[1] = 1f / beam.dy;
        inverse[2] = 1f / beam.dz;
        float[] root = bvh.boxes; // node 0
        for (int k = 0; k < 3; k++) {
            float largest = bvh.hasTree() ? Math.max(Math.abs(root[k]), Math.abs(root[k + 3])) : 0;
            pad[k] = half[k] + ROUNDING * (2 * largest + Math.abs(centre[k]));
            still[k] = Float.isInfinite(inverse[k]);
            if (!Float.isFinite(pad[k])) {
                return false;
            }
        }
        for (int k = 0; k < 3; k++) {
            fan[k] = beam.spread[k] * (1 + FAN_ROUNDING);
        }
        shortest = beam.shortest;
        longest = beam.longest;
        return true;
    }

    /**
     * The slab test of the middle ray against the box at {@code boxes[at .. at+5]}, grown by the
     * beam's {@link #pad}, by {@code grow}, and by how far the rays fan out up to {@code within}, a t
     * beyond which none of them is in the box; {@link #exit} is left where it leaves.
     */
    float grownEntry(float[] boxes, int at, float grow, float within) {
        float enter = Float.NEGATIVE_INFINITY;
        float leave = Float.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            float widen = pad[k] + grow + (fan[k] > 0 ? fan[k] * within : 0); // 0 · ∞ would be NaN
            float low = boxes[at + k] - widen;
            float high = boxes[at + 3 + k] + widen;
            if (still[k]) { // the rays do not move along axis k
                if (low > centre[k] || high < centre[k]) {
                    exit = MISS;
                    return MISS;
                }
                continue;
            }
            float t0 = (low - centre[k]) * inverse[k];
            float t1 = (high - centre[k]) * inverse[k];
            enter = FastMath.max(enter, FastMath.min(t0, t1));
            leave = FastMath.min(leave, FastMath.max(t0, t1));
        }
        exit = leave;
        return FastMath.max(enter, 0) <= leave ? enter : MISS; // as NearestHit#entry
    }

    /** The beam's entry into the nearest box of the objects of {@code leaf}, or {@link #MISS} if it reaches none. */
    float objectsEntry(int leaf, float grow, float within) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        float entry = MISS;
        for (int i = first; i < end; i++) {
            entry = FastMath.min(entry, objectEntry(i, grow, within));
        }
        return entry;
    }

    /** The beam's entry into the box of the leaves' object {@code i}, or {@link #MISS} if it reaches none. */
    float objectEntry(int i, float grow, float within) {
        return grownEntry(bvh.leaves.boxes, 6 * i, grow, within);
    }
}
