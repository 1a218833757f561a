package rtd.accel;

import java.util.Arrays;
import rtd.camera.Beam;

/**
 * The leaves of a {@link Bvh} that a bundle of parallel rays can reach, sorted by how far
 * along the rays they start. Not in the paper: it serves the orthographic camera, whose rays
 * all share one direction.
 *
 * <p>Neighbouring parallel rays form a beam: the rays from origins O ± h (h the half size of
 * the box around their origins). A ray from such an origin passes through a box exactly when
 * the beam's middle ray passes through the box grown by h. So one walk down the tree with the
 * middle ray and grown boxes finds every leaf that any ray of the bundle could reach, and, for
 * each, a t that no ray of the bundle enters it before. Each ray then tests only those leaves,
 * nearest first, instead of walking the tree itself.
 *
 * <p>The grown boxes grow a little more (a millionth of the numbers involved) than h, so that
 * rounding can never make the beam miss a box that one of its rays enters.
 */
final class BeamLeaves {

    private static final float ROUNDING = 1e-6f;

    private final Bvh bvh;
    private final int[] stack;
    // The beam: the centre and half size of the box around the rays' origins, and 1 / direction.
    private final float[] centre = new float[3];
    private final float[] half = new float[3];
    private final float[] inverse = new float[3];
    private int[] leaves = new int[64];
    private float[] entries = new float[64];
    private long[] sortKeys = new long[64];
    /** Arrays of the same size to sort into, swapped with the two above. */
    private int[] spareLeaves = new int[64];
    private float[] spareEntries = new float[64];
    private int count;
    private long nodesVisited;

    BeamLeaves(Bvh bvh) {
        this.bvh = bvh;
        this.stack = new int[bvh.maxDepth + 2];
    }

    /**
     * Finds the leaves that the beam's rays can reach; false, with no leaves found, if the
     * origins are too far out for float to hold the beam's size.
     */
    boolean collect(Beam beam) {
        float[] lowest = {beam.lowestOrigin().x(), beam.lowestOrigin().y(), beam.lowestOrigin().z()};
        float[] highest = {beam.highestOrigin().x(), beam.highestOrigin().y(), beam.highestOrigin().z()};
        for (int k = 0; k < 3; k++) {
            centre[k] = (lowest[k] + highest[k]) / 2;
            half[k] = (highest[k] - lowest[k]) / 2 + ROUNDING * (Math.abs(lowest[k]) + Math.abs(highest[k]));
            if (!Float.isFinite(centre[k]) || !Float.isFinite(half[k])) {
                this.count = 0;
                return false;
            }
        }
        inverse[0] = 1f / beam.direction().x();
        inverse[1] = 1f / beam.direction().y();
        inverse[2] = 1f / beam.direction().z();
        walk();
        sortByEntry();
        return true;
    }

    private void walk() {
        count = 0;
        int stackSize = 0;
        stack[stackSize++] = 0;
        while (stackSize > 0) {
            int node = stack[--stackSize];
            nodesVisited++;
            if (grownEntry(bvh.bounds, node) == Float.POSITIVE_INFINITY) {
                continue;
            }
            int first = bvh.nodes[2 * node];
            if (bvh.nodes[2 * node + 1] == Bvh.INNER) {
                stack[stackSize++] = first + 1;
                stack[stackSize++] = first;
            } else {
                addIfAnObjectIsReached(node);
            }
        }
    }

    /**
     * Adds the leaf if the beam reaches the box of one of its objects, with the nearest entry
     * into those boxes: a small scene's few objects may share one leaf whose box covers much
     * of the picture, while the objects themselves cover little of it.
     */
    private void addIfAnObjectIsReached(int leaf) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        float entry = Float.POSITIVE_INFINITY;
        for (int i = first; i < end; i++) {
            entry = FastMath.min(entry, grownEntry(bvh.objectBounds, i));
        }
        if (entry != Float.POSITIVE_INFINITY) {
            add(leaf, entry);
        }
    }

    /** The slab test of the middle ray against box {@code i} of {@code boxes}, grown by {@code half}. */
    private float grownEntry(float[] boxes, int i) {
        float enter = Float.NEGATIVE_INFINITY;
        float exit = Float.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            float min = boxes[6 * i + k];
            float max = boxes[6 * i + 3 + k];
            float grow = half[k] + ROUNDING * (Math.abs(min) + Math.abs(max) + Math.abs(centre[k]));
            if (Float.isInfinite(inverse[k])) { // the rays do not move along axis k
                if (min - grow > centre[k] || max + grow < centre[k]) {
                    return Float.POSITIVE_INFINITY;
                }
                continue;
            }
            float t0 = (min - grow - centre[k]) * inverse[k];
            float t1 = (max + grow - centre[k]) * inverse[k];
            enter = FastMath.max(enter, FastMath.min(t0, t1));
            exit = FastMath.min(exit, FastMath.max(t0, t1));
        }
        return enter <= exit && exit >= 0 ? enter : Float.POSITIVE_INFINITY;
    }

    private void add(int leaf, float entry) {
        if (count == leaves.length) {
            leaves = Arrays.copyOf(leaves, 2 * count);
            entries = Arrays.copyOf(entries, 2 * count);
            sortKeys = Arrays.copyOf(sortKeys, 2 * count);
            spareLeaves = new int[2 * count];
            spareEntries = new float[2 * count];
        }
        leaves[count] = leaf;
        entries[count] = entry;
        count++;
    }

    /** Sorts the leaves by entry, nearest first (on a tie, in tree order). */
    private void sortByEntry() {
        for (int i = 0; i < count; i++) {
            sortKeys[i] = (long) orderedBits(entries[i]) << 32 | i;
        }
        Arrays.sort(sortKeys, 0, count);
        int[] unsortedLeaves = leaves;
        float[] unsortedEntries = entries;
        leaves = spareLeaves;
        entries = spareEntries;
        for (int i = 0; i < count; i++) {
            int from = (int) sortKeys[i];
            leaves[i] = unsortedLeaves[from];
            entries[i] = unsortedEntries[from];
        }
        spareLeaves = unsortedLeaves;
        spareEntries = unsortedEntries;
    }

    /** The float's bits turned so that signed int order is the float's order. */
    private static int orderedBits(float value) {
        int bits = Float.floatToIntBits(value);
        return bits >= 0 ? bits : bits ^ 0x7FFFFFFF;
    }

    int count() {
        return count;
    }

    int leaf(int i) {
        return leaves[i];
    }

    /** No ray of the bundle enters leaf {@code i} before this t. */
    float entry(int i) {
        return entries[i];
    }

    long nodesVisited() {
        return nodesVisited;
    }
}
