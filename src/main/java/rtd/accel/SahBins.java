package rtd.accel;

import java.util.Arrays;

/**
 * The bins of one axis for the surface area heuristic: per bin, how many object centres fell
 * in it and the box around their boxes. {@link #splitCosts} sweeps them from both ends; a
 * child's box is the union of its bins' ({@link #box}), so no second pass over its objects is
 * needed (the partition finds the box of the child's centres).
 *
 * <p>The bins are flat arrays, and the pass over a node's objects ({@link #add(float[], int,
 * int, int, float, float)}) is one loop here: the JIT compiles a short loop early, which
 * matters for a build that runs once.
 */
final class SahBins {

    /** The number of bins. */
    static final int COUNT = 16;

    private final int[] counts = new int[COUNT];
    /** Per bin, the box around its objects' boxes: six floats from {@code 6·bin}. */
    private final float[] boxes = new float[6 * COUNT];
    private final float[] costs = new float[COUNT - 1];
    /** The box of the bins swept so far, min x, y, z, max x, y, z. */
    private final float[] sweep = new float[6];

    SahBins() {
        clear();
    }

    /** Empties every bin. */
    void clear() {
        Arrays.fill(counts, 0);
        for (int b = 0; b < COUNT; b++) {
            Extent.setEmpty(boxes, 6 * b);
        }
    }

    /**
     * The bin of a centre, for bins that start at {@code lo} and have {@code scale} bins per
     * unit; the same for the binning and the partition that follows it.
     */
    static int binOf(float centre, float lo, float scale) {
        int bin = (int) ((centre - lo) * scale);
        return Math.min(COUNT - 1, Math.max(0, bin));
    }

    /**
     * Adds the objects whose boxes are at {@code boxes[6i .. 6i+5]} for i in {@code [from, to)},
     * each to the bin of its centre along {@code axis} ({@link #binOf}).
     */
    void add(float[] objectBoxes, int from, int to, int axis, float lo, float scale) {
        for (int i = from; i < to; i++) {
            int at = 6 * i;
            int bin = binOf((objectBoxes[at + axis] + objectBoxes[at + axis + 3]) * 0.5f, lo, scale);
            counts[bin]++;
            Extent.grow(boxes, 6 * bin, objectBoxes, at);
        }
    }

    /** Adds the objects of {@code other}'s bins to these, bin by bin. */
    void add(SahBins other) {
        for (int b = 0; b < COUNT; b++) {
            counts[b] += other.counts[b];
            Extent.grow(boxes, 6 * b, other.boxes, 6 * b);
        }
    }

    /** How many objects bins {@code [0, to)} hold. */
    int count(int to) {
        int n = 0;
        for (int b = 0; b < to; b++) {
            n += counts[b];
        }
        return n;
    }

    /**
     * For each split between bin {@code s} and {@code s + 1}: area(left box) · left count +
     * area(right box) · right count, or infinity if one side would be empty. The array is
     * reused by the next call.
     */
    float[] splitCosts() {
        Extent.setEmpty(sweep);
        int n = 0;
        for (int s = 0; s < COUNT - 1; s++) {
            n += counts[s];
            Extent.grow(sweep, 0, boxes, 6 * s);
            costs[s] = n == 0 ? Float.POSITIVE_INFINITY : area(sweep, 0) * n;
        }
        Extent.setEmpty(sweep);
        n = 0;
        for (int s = COUNT - 1; s > 0; s--) {
            n += counts[s];
            Extent.grow(sweep, 0, boxes, 6 * s);
            costs[s - 1] = n == 0 ? Float.POSITIVE_INFINITY : costs[s - 1] + area(sweep, 0) * n;
        }
        return costs;
    }

    /**
     * A new extent whose box is the union of bins {@code [from, to)}; its box of centres is
     * left empty, for the partition to fill in.
     */
    Extent box(int from, int to) {
        Extent union = Extent.empty();
        for (int b = from; b < to; b++) {
            if (counts[b] > 0) {
                Extent.grow(union.box(), 0, boxes, 6 * b);
            }
        }
        return union;
    }

    /** The surface area of the box at {@code box[at .. at+5]}. */
    static float area(float[] box, int at) {
        float dx = box[at + 3] - box[at];
        float dy = box[at + 4] - box[at + 1];
        float dz = box[at + 5] - box[at + 2];
        return 2 * (dx * dy + dy * dz + dz * dx);
    }
}
