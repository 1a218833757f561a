package rtd.accel;

import java.util.Arrays;

/**
 * The bins of one axis for the surface area heuristic: per bin, how many object centres fell
 * in it, the box around their boxes and the box around their centres. {@link #splitCosts}
 * sweeps them from both ends; a child's {@link Extent} is the union of its bins'
 * ({@link #extent}), so no second pass over its objects is needed.
 *
 * <p>The bins are flat arrays, and the pass over a node's objects ({@link #add(float[], int,
 * int, int, float, float)}) is one loop here: the JIT compiles a short loop early, which
 * matters for a build that runs once.
 */
final class SahBins {

    /** The number of bins. */
    static final int COUNT = 16;

    /**
     * From this many objects on, {@link #add} grows the bins' boxes by comparisons that the
     * processor predicts, below it without branches.
     */
    private static final int MANY = 8192;

    private final int[] counts = new int[COUNT];
    /** Per bin, the box around its objects' boxes: six floats from {@code 6·bin}. */
    private final float[] boxes = new float[6 * COUNT];
    /** Per bin, the box around its objects' centres: six floats from {@code 6·bin}. */
    private final float[] centres = new float[6 * COUNT];
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
            Extent.setEmpty(centres, 6 * b);
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
     * each to the bin of its centre along {@code axis} ({@link #binOf}): {@link #addMany} or
     * {@link #addFew}, by their number.
     */
    void add(float[] objectBoxes, int from, int to, int axis, float lo, float scale) {
        if (to - from >= MANY) {
            addMany(objectBoxes, from, to, axis, lo, scale);
        } else {
            addFew(objectBoxes, from, to, axis, lo, scale);
        }
    }

    /**
     * {@link #add} for many objects, at least {@value #MANY}. Its own method, and the loop of
     * {@link #addFew} another: the JIT compiles each loop while it runs, and one method with
     * both, compiled in the top levels of the tree where only this loop runs, would be
     * compiled again when the other is first taken.
     */
    void addMany(float[] objectBoxes, int from, int to, int axis, float lo, float scale) {
        for (int i = from; i < to; i++) {
            int at = 6 * i;
            int bin = binOf((objectBoxes[at + axis] + objectBoxes[at + axis + 3]) * 0.5f, lo, scale);
            counts[bin]++;
            addRarelyGrowing(6 * bin, objectBoxes, at);
        }
    }

    /** {@link #add} for fewer than {@value #MANY} objects. */
    private void addFew(float[] objectBoxes, int from, int to, int axis, float lo, float scale) {
        for (int i = from; i < to; i++) {
            int at = 6 * i;
            int bin = binOf((objectBoxes[at + axis] + objectBoxes[at + axis + 3]) * 0.5f, lo, scale);
            counts[bin]++;
            addOftenGrowing(6 * bin, objectBoxes, at);
        }
    }

    /**
     * Grows bin {@code bin}'s boxes by an object's, by a comparison each: with many objects per
     * bin, the boxes soon reach their size and the comparisons go the same way almost always,
     * which the processor predicts.
     */
    private void addRarelyGrowing(int bin, float[] objectBoxes, int at) {
        for (int k = 0; k < 3; k++) {
            float min = objectBoxes[at + k];
            float max = objectBoxes[at + k + 3];
            boxes[bin + k] = FastMath.min(boxes[bin + k], min);
            boxes[bin + k + 3] = FastMath.max(boxes[bin + k + 3], max);
            float centre = (min + max) * 0.5f;
            centres[bin + k] = FastMath.min(centres[bin + k], centre);
            centres[bin + k + 3] = FastMath.max(centres[bin + k + 3], centre);
        }
    }

    /**
     * Grows bin {@code bin}'s boxes by an object's, without branches ({@link Math#min} is
     * compiled to a fixed sequence of instructions): with few objects per bin, about every
     * other comparison would be mispredicted. For the finite boxes the builder bins it gives
     * the numbers of {@link #addRarelyGrowing} (at most the sign of a zero differs, which no
     * comparison sees), so which of the two runs does not change the tree.
     */
    private void addOftenGrowing(int bin, float[] objectBoxes, int at) {
        for (int k = 0; k < 3; k++) {
            float min = objectBoxes[at + k];
            float max = objectBoxes[at + k + 3];
            boxes[bin + k] = Math.min(boxes[bin + k], min);
            boxes[bin + k + 3] = Math.max(boxes[bin + k + 3], max);
            float centre = (min + max) * 0.5f;
            centres[bin + k] = Math.min(centres[bin + k], centre);
            centres[bin + k + 3] = Math.max(centres[bin + k + 3], centre);
        }
    }

    /** Adds the objects of {@code other}'s bins to these, bin by bin. */
    void add(SahBins other) {
        for (int b = 0; b < COUNT; b++) {
            counts[b] += other.counts[b];
            Extent.grow(boxes, 6 * b, other.boxes, 6 * b);
            Extent.grow(centres, 6 * b, other.centres, 6 * b);
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

    /** A new extent, the union of bins {@code [from, to)}. */
    Extent extent(int from, int to) {
        Extent union = Extent.empty();
        for (int b = from; b < to; b++) {
            if (counts[b] > 0) {
                Extent.grow(union.box(), 0, boxes, 6 * b);
                Extent.grow(union.centres(), 0, centres, 6 * b);
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
