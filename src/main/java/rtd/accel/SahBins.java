package rtd.accel;

import java.util.Arrays;

/**
 * The bins of one axis for the surface area heuristic: per bin, how many object centres fell
 * in it and the box around those objects. {@link #splitCosts} sweeps them from both ends.
 */
final class SahBins {

    private final int[] counts;
    /** Per bin: min x, y, z, max x, y, z. */
    private final float[] boxes;

    private final float[] costs;
    private final float[] sweep = new float[6];

    SahBins(int binCount) {
        counts = new int[binCount];
        boxes = new float[6 * binCount];
        costs = new float[binCount - 1];
        clear();
    }

    /** Empties every bin. */
    void clear() {
        Arrays.fill(counts, 0);
        for (int b = 0; b < counts.length; b++) {
            setEmpty(boxes, 6 * b);
        }
    }

    /** Adds an object, whose box is {@code objectBoxes[at .. at+5]}, to {@code bin}. */
    void add(int bin, float[] objectBoxes, int at) {
        counts[bin]++;
        grow(boxes, 6 * bin, objectBoxes, at);
    }

    /**
     * For each split between bin {@code s} and {@code s + 1}: area(left box) · left count +
     * area(right box) · right count, or infinity if one side would be empty. The array is
     * reused by the next call.
     */
    float[] splitCosts() {
        int bins = counts.length;
        float[] box = sweep;
        setEmpty(box, 0);
        int n = 0;
        for (int s = 0; s < bins - 1; s++) {
            n += counts[s];
            grow(box, 0, boxes, 6 * s);
            costs[s] = n == 0 ? Float.POSITIVE_INFINITY : area(box, 0) * n;
        }
        setEmpty(box, 0);
        n = 0;
        for (int s = bins - 1; s > 0; s--) {
            n += counts[s];
            grow(box, 0, boxes, 6 * s);
            costs[s - 1] = n == 0 ? Float.POSITIVE_INFINITY : costs[s - 1] + area(box, 0) * n;
        }
        return costs;
    }

    /** The surface area of the box at {@code box[at .. at+5]}. */
    static float area(float[] box, int at) {
        float dx = box[at + 3] - box[at];
        float dy = box[at + 4] - box[at + 1];
        float dz = box[at + 5] - box[at + 2];
        return 2 * (dx * dy + dy * dz + dz * dx);
    }

    private static void setEmpty(float[] box, int at) {
        for (int k = 0; k < 3; k++) {
            box[at + k] = Float.POSITIVE_INFINITY;
            box[at + k + 3] = Float.NEGATIVE_INFINITY;
        }
    }

    private static void grow(float[] box, int at, float[] other, int otherAt) {
        for (int k = 0; k < 3; k++) {
            box[at + k] = FastMath.min(box[at + k], other[otherAt + k]);
            box[at + k + 3] = FastMath.max(box[at + k + 3], other[otherAt + k + 3]);
        }
    }
}
