package rtd.accel;

import java.util.Arrays;

/**
 * The bins of one axis for the surface area heuristic: per bin, how many object centres fell
 * in it and their {@link Extent}. {@link #splitCosts} sweeps them from both ends; a child's
 * extent is the union of its bins' ({@link #extent}), so no second pass over its objects is needed.
 */
final class SahBins {

    private final int[] counts;
    private final Extent[] extents;
    private final float[] costs;
    /** The box of the bins swept so far, min x, y, z, max x, y, z. */
    private final float[] sweep = new float[6];

    SahBins(int binCount) {
        counts = new int[binCount];
        extents = new Extent[binCount];
        for (int b = 0; b < binCount; b++) {
            extents[b] = Extent.empty();
        }
        costs = new float[binCount - 1];
    }

    /** Empties every bin. */
    void clear() {
        Arrays.fill(counts, 0);
        for (Extent extent : extents) {
            extent.clear();
        }
    }

    /** Adds an object, with its box at {@code boxes[boxAt ..]} and centre at {@code centres[centreAt ..]}, to {@code bin}. */
    void add(int bin, float[] boxes, int boxAt, float[] centres, int centreAt) {
        counts[bin]++;
        extents[bin].add(boxes, boxAt, centres, centreAt);
    }

    /**
     * For each split between bin {@code s} and {@code s + 1}: area(left box) · left count +
     * area(right box) · right count, or infinity if one side would be empty. The array is
     * reused by the next call.
     */
    float[] splitCosts() {
        int bins = counts.length;
        Extent.setEmpty(sweep);
        int n = 0;
        for (int s = 0; s < bins - 1; s++) {
            n += counts[s];
            Extent.grow(sweep, extents[s].box());
            costs[s] = n == 0 ? Float.POSITIVE_INFINITY : area(sweep, 0) * n;
        }
        Extent.setEmpty(sweep);
        n = 0;
        for (int s = bins - 1; s > 0; s--) {
            n += counts[s];
            Extent.grow(sweep, extents[s].box());
            costs[s - 1] = n == 0 ? Float.POSITIVE_INFINITY : costs[s - 1] + area(sweep, 0) * n;
        }
        return costs;
    }

    /** A new extent, the union of bins {@code [from, to)}. */
    Extent extent(int from, int to) {
        Extent union = Extent.empty();
        for (int b = from; b < to; b++) {
            if (counts[b] > 0) {
                union.add(extents[b]);
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
