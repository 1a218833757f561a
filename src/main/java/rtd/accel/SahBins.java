package rtd.accel;

import java.util.Arrays;

/**
 * The bins of the surface area heuristic along one axis of a node ({@link BvhBuilder}), and the
 * <em>extents</em> it works with: twelve floats, the box around a group's boxes (min x, y, z,
 * max x, y, z) and the box around their centres, the centre of a box being
 * {@code (min + max) · 0.5} in float as {@link rtd.geometry.BoundingBox#centre} computes it.
 *
 * <p>Each object goes to the bin of its centre; the cost of the split between two bins is
 * area(left box) · left count + area(right box) · right count, the expected number of tests of a
 * ray through the node, up to a factor. A child's extent is the union of its bins', exactly what
 * a pass over its objects would measure.
 */
final class SahBins {

    static final int COUNT = 16;
    static final int EXTENT = 12;
    static final int CENTRES = 6;
    /** From this many objects on, {@link #fill} grows the bins by comparisons the processor predicts. */
    private static final int MANY = 8192;

    private final int[] counts = new int[COUNT];
    /** Per bin, its extent, {@value #EXTENT} floats from {@code EXTENT·bin}. */
    private final float[] bins = new float[EXTENT * COUNT];
    /** Per split between bin s and s + 1, its cost. */
    private final float[] costs = new float[COUNT - 1];
    private final float[] sweep = new float[EXTENT];

    /** Fills the bins with the objects whose boxes are {@code boxes[6i .. 6i+5]}, i in {@code [start, end)}. */
    void fill(float[] boxes, int start, int end, int axis, float lo, float scale) {
        Arrays.fill(counts, 0);
        for (int b = 0; b < COUNT; b++) {
            setEmpty(bins, EXTENT * b);
        }
        if (end - start >= MANY) {
            addMany(boxes, start, end, axis, lo, scale);
        } else {
            addFew(boxes, start, end, axis, lo, scale);
        }
    }

    /** {@link #fill} for few objects, which grow a bin's box often: without branches ({@link #add}). */
    private void addFew(float[] boxes, int start, int end, int axis, float lo, float scale) {
        for (int i = start; i < end; i++) {
            int bin = binOf((boxes[6 * i + axis] + boxes[6 * i + axis + 3]) * 0.5f, lo, scale);
            counts[bin]++;
            add(bins, EXTENT * bin, boxes, 6 * i);
        }
    }

    /**
     * {@link #fill} for many objects: a bin's box soon reaches its size, and the comparisons go the
     * same way almost always, which the processor predicts ({@link FastMath}); the numbers are
     * {@link #add}'s but for the sign of a zero, which no comparison sees. A method of its own, so
     * that the JIT compiles each of the two loops on its own, while it runs.
     */
    private void addMany(float[] boxes, int start, int end, int axis, float lo, float scale) {
        for (int i = start; i < end; i++) {
            int bin = binOf((boxes[6 * i + axis] + boxes[6 * i + axis + 3]) * 0.5f, lo, scale);
            counts[bin]++;
            int at = EXTENT * bin;
            for (int k = 0; k < 3; k++) {
                float min = boxes[6 * i + k];
                float max = boxes[6 * i + k + 3];
                float centre = (min + max) * 0.5f;
                bins[at + k] = FastMath.min(bins[at + k], min);
                bins[at + k + 3] = FastMath.max(bins[at + k + 3], max);
                bins[at + CENTRES + k] = FastMath.min(bins[at + CENTRES + k], centre);
                bins[at + CENTRES + k + 3] = FastMath.max(bins[at + CENTRES + k + 3], centre);
            }
        }
    }

    /** The bin of a centre, for bins from {@code lo} at {@code scale} bins a unit: for binning and partition. */
    static int binOf(float centre, float lo, float scale) {
        return Math.min(COUNT - 1, Math.max(0, (int) ((centre - lo) * scale)));
    }

    /** The last bin of the left side of the cheapest split, sweeping from both ends, or −1 if none has two sides. */
    int cheapestSplit() {
        setEmpty(sweep, 0);
        for (int s = 0, n = 0; s < COUNT - 1; s++) {
            n += counts[s];
            union(sweep, 0, bins, EXTENT * s);
            costs[s] = n == 0 ? Float.POSITIVE_INFINITY : area(sweep) * n;
        }
        setEmpty(sweep, 0);
        for (int s = COUNT - 1, n = 0; s > 0; s--) {
            n += counts[s];
            union(sweep, 0, bins, EXTENT * s);
            costs[s - 1] = n == 0 ? Float.POSITIVE_INFINITY : costs[s - 1] + area(sweep) * n;
        }
        int best = -1;
        for (int s = 0; s < COUNT - 1; s++) {
            if (costs[s] < (best < 0 ? Float.POSITIVE_INFINITY : costs[best])) {
                best = s;
            }
        }
        return best;
    }

    /** The cost of split {@code split} ({@link #cheapestSplit}), infinite for −1. */
    float cost(int split) {
        return split < 0 ? Float.POSITIVE_INFINITY : costs[split];
    }

    /** How many objects bins {@code [0, to)} hold. */
    int count(int to) {
        int n = 0;
        for (int b = 0; b < to; b++) {
            n += counts[b];
        }
        return n;
    }

    /** A new extent, the union of bins {@code [from, to)}. */
    float[] extent(int from, int to) {
        float[] extent = empty();
        for (int b = from; b < to; b++) {
            union(extent, 0, bins, EXTENT * b);
            union(extent, CENTRES, bins, EXTENT * b + CENTRES);
        }
        return extent;
    }

    /** A new empty extent, which grows into any it is grown by. */
    static float[] empty() {
        float[] extent = new float[EXTENT];
        setEmpty(extent, 0);
        return extent;
    }

    private static void setEmpty(float[] extent, int at) {
        for (int k = 0; k < 3; k++) {
            extent[at + k] = Float.POSITIVE_INFINITY;
            extent[at + k + 3] = Float.NEGATIVE_INFINITY;
            extent[at + CENTRES + k] = Float.POSITIVE_INFINITY;
            extent[at + CENTRES + k + 3] = Float.NEGATIVE_INFINITY;
        }
    }

    /** Grows the extent at {@code extent[at ..]} by the object whose box is {@code box[b .. b+5]}. */
    static void add(float[] extent, int at, float[] box, int b) {
        for (int k = 0; k < 3; k++) {
            float min = box[b + k];
            float max = box[b + k + 3];
            extent[at + k] = Math.min(extent[at + k], min);
            extent[at + k + 3] = Math.max(extent[at + k + 3], max);
            float centre = (min + max) * 0.5f;
            extent[at + CENTRES + k] = Math.min(extent[at + CENTRES + k], centre);
            extent[at + CENTRES + k + 3] = Math.max(extent[at + CENTRES + k + 3], centre);
        }
    }

    /** Grows the box at {@code box[at .. at+5]} by the box at {@code other[o .. o+5]}: an extent's, or its centres'. */
    private static void union(float[] box, int at, float[] other, int o) {
        for (int k = 0; k < 3; k++) {
            box[at + k] = Math.min(box[at + k], other[o + k]);
            box[at + k + 3] = Math.max(box[at + k + 3], other[o + k + 3]);
        }
    }

    /** The axis along which the centres of {@code extent} spread most, or −1 if they all coincide. */
    static int widestAxis(float[] extent) {
        int axis = -1;
        float widest = 0;
        for (int k = 0; k < 3; k++) {
            float spread = extent[CENTRES + k + 3] - extent[CENTRES + k];
            if (spread > widest) {
                widest = spread;
                axis = k;
            }
        }
        return axis;
    }

    /** The surface area of an extent's box. */
    static float area(float[] extent) {
        float dx = extent[3] - extent[0];
        float dy = extent[4] - extent[1];
        float dz = extent[5] - extent[2];
        return 2 * (dx * dy + dy * dz + dz * dx);
    }
}
