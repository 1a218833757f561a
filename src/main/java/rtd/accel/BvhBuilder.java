package rtd.accel;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import rtd.geometry.IGeometry;

/**
 * Builds the tree of a {@link Bvh} top-down with the binned surface area heuristic (SAH), as
 * pbrt's BVH does: a node's object centres are sorted into {@value #BINS} bins along the axis
 * where they spread most, and the node divides between the two bins where the expected cost is
 * least, a child's cost being its box's surface area (how likely a ray passes through it) times
 * its object count; it becomes a leaf when no split is cheaper than testing its objects.
 *
 * <p>An <em>extent</em> is twelve floats: the box around a group's boxes (min x, y, z, max x, y,
 * z), then the box around their centres, the centre of a box being {@code (min + max) · 0.5} in
 * float as {@link rtd.geometry.BoundingBox#centre} computes it. A child's extent is the union of
 * its bins', exactly what a pass over its objects would measure.
 *
 * <p>A node's objects are partitioned by copying them, in order, from one of two sets of arrays
 * into the other; the children partition them back, and a leaf's objects end in the first set.
 * Nodes are numbered depth first, the two children of a node side by side, in the {@link Bvh}'s
 * layout. Where all centres of a node coincide the SAH has nothing to go by: the twins of earlier
 * objects are left out ({@link #withoutTwins}) and the rest halved by count, as in very deep trees.
 * It builds on one thread, in a loop over the nodes waiting, which the JIT compiles while it runs.
 */
final class BvhBuilder {

    private static final int BINS = 16;
    private static final int MAX_LEAF_SIZE = 16;
    /** Past this depth nodes are halved by count, which bounds the depth for any input. */
    private static final int MAX_SAH_DEPTH = 48;
    /**
     * The cost of visiting a node, counted in intersection tests: with leaves of up to 16 it makes
     * shallow trees of full leaves, which a walk that waits for memory at each node favours.
     */
    private static final float TRAVERSAL_COST = 4f;
    private static final int EXTENT = 12;
    private static final int CENTRES = 6;

    private final List<IGeometry> objects;
    /** The objects with a finite box, which the tree holds: places {@code [0, count)}. */
    private final int count;
    /** The places in the file of the objects without one (planes), in file order. */
    private final int[] unbounded;
    /** Two sets of the objects' places in the file and their boxes (six floats a place); set 0 ends in leaf order. */
    private final int[][] orders;
    private final float[][] objectBoxes;
    private final int[] binCounts = new int[BINS];
    /** Per bin, its extent, {@value #EXTENT} floats. */
    private final float[] bins = new float[EXTENT * BINS];
    private final float[] costs = new float[BINS - 1];
    /** The extent of the bins swept so far. */
    private final float[] sweep = new float[EXTENT];
    private float[] boxes;
    private int[] nodes;
    private int nodeCount = 1;
    private int maxDepth;

    /** A builder for {@code objects}: each box measured once, the objects without a finite one set apart. */
    BvhBuilder(List<IGeometry> objects) {
        this.objects = objects;
        int n = objects.size();
        orders = new int[][] {new int[n], new int[n]};
        objectBoxes = new float[][] {new float[6 * n], new float[6 * n]};
        int kept = 0;
        int[] apart = new int[n];
        int apartCount = 0;
        for (int f = 0; f < n; f++) {
            KnownShapes.putBox(objects.get(f), objectBoxes[0], 6 * kept);
            if (isFinite(objectBoxes[0], 6 * kept)) {
                orders[0][kept++] = f;
            } else {
                apart[apartCount++] = f;
            }
        }
        count = kept;
        unbounded = Arrays.copyOf(apart, apartCount);
        System.arraycopy(unbounded, 0, orders[0], count, apartCount);
        int room = Math.max(64, count / 2); // leaves of four objects or more, as the SAH makes them
        boxes = new float[Bvh.BOX * room];
        nodes = new int[2 * room];
    }

    int count() {
        return count;
    }

    int[] unbounded() {
        return unbounded;
    }

    /** The objects' places in the file, in leaf order ({@link #count} of them), then those without a box. */
    int[] order() {
        return orders[0];
    }

    /** The second set of arrays, which the tree no longer needs once built: room for {@link LeafObjects}. */
    int[] spareInts() {
        return orders[1];
    }

    float[] spareFloats() {
        return objectBoxes[1];
    }

    /** Each node's box at {@code Bvh.BOX·i}, its rounding not yet filled in. */
    float[] boxes() {
        return boxes;
    }

    int[] nodes() {
        return nodes;
    }

    int maxDepth() {
        return maxDepth;
    }

    /** A node that waits to be built: its places in set {@code side}, and its extent if known. */
    private record Pending(int node, int start, int end, int depth, float[] extent, int side) {
    }

    /** Builds the tree. */
    void build() {
        ArrayDeque<Pending> waiting = new ArrayDeque<>();
        waiting.push(new Pending(0, 0, count, 0, null, 0));
        while (!waiting.isEmpty()) {
            Pending next = waiting.pop();
            Pending[] children = split(next);
            if (children == null) {
                maxDepth = Math.max(maxDepth, next.depth());
            } else {
                waiting.push(children[1]);
                waiting.push(children[0]);
            }
        }
        boxes = Arrays.copyOf(boxes, Bvh.BOX * nodeCount);
        nodes = Arrays.copyOf(nodes, 2 * nodeCount);
    }

    /** Makes the {@code waiting} node a leaf (answers null) or an inner node, and answers its children. */
    private Pending[] split(Pending waiting) {
        int start = waiting.start();
        int end = waiting.end();
        int side = waiting.side();
        float[] extent = waiting.extent() != null ? waiting.extent() : measure(side, start, end);
        System.arraycopy(extent, 0, boxes, Bvh.BOX * waiting.node(), 6);
        int axis = widestAxis(extent);
        if (end - start > 1 && axis < 0) {
            end = withoutTwins(side, start, end);
        }
        Pending[] children = end - start <= 1 ? null
                : waiting.depth() >= MAX_SAH_DEPTH || axis < 0 && end - start > MAX_LEAF_SIZE ? byCount(waiting, end)
                : axis < 0 ? null : bySah(waiting, end, extent, axis);
        if (children == null) {
            if (side != 0) {
                copy(side, start, end);
            }
            nodes[2 * waiting.node()] = start;
            nodes[2 * waiting.node() + 1] = end - start;
            return null;
        }
        nodes[2 * waiting.node()] = children[0].node();
        nodes[2 * waiting.node() + 1] = Bvh.INNER;
        return children;
    }

    /** The children of the cheapest split by the SAH, its objects partitioned into the other set; null for a leaf. */
    private Pending[] bySah(Pending node, int end, float[] extent, int axis) {
        int start = node.start();
        int n = end - start;
        float area = area(extent, 0);
        if (n <= TRAVERSAL_COST && area > 0 && area < Float.POSITIVE_INFINITY) {
            return null; // a split costs at least a visit, more than these objects' tests
        }
        float lo = extent[CENTRES + axis];
        float scale = BINS / (extent[CENTRES + axis + 3] - lo);
        fillBins(node.side(), start, end, axis, lo, scale);
        int bestBin = cheapestSplit();
        float bestCost = bestBin < 0 ? Float.POSITIVE_INFINITY : costs[bestBin];
        if (TRAVERSAL_COST + bestCost / area >= n && n <= MAX_LEAF_SIZE) {
            return null;
        }
        int middle = start;
        for (int b = 0; b <= bestBin; b++) {
            middle += binCounts[b];
        }
        if (middle == start || middle == end) {
            return byCount(node, end);
        }
        int to = 1 - node.side();
        scatter(node.side(), start, end, axis, lo, scale, bestBin, middle);
        int left = pair();
        return new Pending[] {new Pending(left, start, middle, node.depth() + 1, binsExtent(0, bestBin + 1), to),
                new Pending(left + 1, middle, end, node.depth() + 1, binsExtent(bestBin + 1, BINS), to)};
    }

    /** Halves a node's objects by count in their present order; the children measure their extents. */
    private Pending[] byCount(Pending node, int end) {
        int middle = node.start() + (end - node.start()) / 2;
        int left = pair();
        return new Pending[] {new Pending(left, node.start(), middle, node.depth() + 1, null, node.side()),
                new Pending(left + 1, middle, end, node.depth() + 1, null, node.side())};
    }

    /** Two new node numbers side by side, for the children of an inner node; answers the first. */
    private int pair() {
        int first = nodeCount;
        nodeCount += 2;
        if (2 * nodeCount > nodes.length) {
            boxes = Arrays.copyOf(boxes, 2 * boxes.length);
            nodes = Arrays.copyOf(nodes, 2 * nodes.length);
        }
        return first;
    }

    /** Counts the objects of places {@code [start, end)} of set {@code side} into the bins of their centres. */
    private void fillBins(int side, int start, int end, int axis, float lo, float scale) {
        Arrays.fill(binCounts, 0);
        for (int b = 0; b < BINS; b++) {
            setEmpty(bins, EXTENT * b);
        }
        float[] from = objectBoxes[side];
        for (int i = start; i < end; i++) {
            int bin = binOf((from[6 * i + axis] + from[6 * i + axis + 3]) * 0.5f, lo, scale);
            binCounts[bin]++;
            add(bins, EXTENT * bin, from, 6 * i);
        }
    }

    /** The bin of a centre, for bins from {@code lo} at {@code scale} bins a unit: the same for binning and partition. */
    private static int binOf(float centre, float lo, float scale) {
        return Math.min(BINS - 1, Math.max(0, (int) ((centre - lo) * scale)));
    }

    /**
     * Fills {@link #costs}, for the split between bin s and s + 1, with area(left box) · left count
     * + area(right box) · right count (infinite where a side is empty), sweeping from both ends;
     * answers the cheapest, or −1 if none has two sides.
     */
    private int cheapestSplit() {
        setEmpty(sweep, 0);
        for (int s = 0, n = 0; s < BINS - 1; s++) {
            n += binCounts[s];
            union(sweep, 0, bins, EXTENT * s);
            costs[s] = n == 0 ? Float.POSITIVE_INFINITY : area(sweep, 0) * n;
        }
        setEmpty(sweep, 0);
        for (int s = BINS - 1, n = 0; s > 0; s--) {
            n += binCounts[s];
            union(sweep, 0, bins, EXTENT * s);
            costs[s - 1] = n == 0 ? Float.POSITIVE_INFINITY : costs[s - 1] + area(sweep, 0) * n;
        }
        int best = -1;
        float bestCost = Float.POSITIVE_INFINITY;
        for (int s = 0; s < BINS - 1; s++) {
            if (costs[s] < bestCost) {
                bestCost = costs[s];
                best = s;
            }
        }
        return best;
    }

    /** A new extent, the union of bins {@code [from, to)}. */
    private float[] binsExtent(int from, int to) {
        float[] extent = new float[EXTENT];
        setEmpty(extent, 0);
        for (int b = from; b < to; b++) {
            union(extent, 0, bins, EXTENT * b);
        }
        return extent;
    }

    /**
     * Copies places {@code [start, end)} of set {@code side} to the other set, keeping their order:
     * those in a bin {@code ≤ lastLeftBin} from {@code start} on, the others from {@code right} on.
     * Without a branch on the side: which side an object goes to is as good as random, and a
     * mispredicted branch per object costs more than the copy.
     */
    private void scatter(int side, int start, int end, int axis, float lo, float scale, int lastLeftBin, int right) {
        int[] order = orders[side];
        float[] from = objectBoxes[side];
        int[] toOrder = orders[1 - side];
        float[] to = objectBoxes[1 - side];
        int left = start;
        for (int i = start; i < end; i++) {
            int at = 6 * i;
            int bin = binOf((from[at + axis] + from[at + axis + 3]) * 0.5f, lo, scale);
            int goesRight = (lastLeftBin - bin) >>> 31; // the sign bit: 1 if bin > lastLeftBin
            int place = left + ((right - left) & -goesRight);
            left += 1 - goesRight;
            right += goesRight;
            toOrder[place] = order[i];
            int p6 = 6 * place;
            to[p6] = from[at];
            to[p6 + 1] = from[at + 1];
            to[p6 + 2] = from[at + 2];
            to[p6 + 3] = from[at + 3];
            to[p6 + 4] = from[at + 4];
            to[p6 + 5] = from[at + 5];
        }
    }

    /**
     * Moves the objects of places {@code [start, end)} that are the twin of one before them in the
     * file ({@link KnownShapes#twinKey}) behind the others, and answers where they start: the tree
     * leaves them out. A twin reports the same hit as the first of its kind for every ray, and on
     * that tie the first in the file wins. Asked only where all centres coincide, the one place
     * where many twins can gather and defeat the tree.
     */
    private int withoutTwins(int side, int start, int end) {
        int[] order = orders[side];
        Arrays.sort(order, start, end); // file order, so that the first of each kind is kept
        Map<Object, Boolean> seen = new HashMap<>();
        int kept = start;
        for (int i = start; i < end; i++) {
            if (seen.putIfAbsent(KnownShapes.twinKey(objects.get(order[i])), Boolean.TRUE) == null) {
                int object = order[i];
                order[i] = order[kept];
                order[kept++] = object;
            }
        }
        for (int i = start; i < end; i++) {
            KnownShapes.putBox(objects.get(order[i]), objectBoxes[side], 6 * i);
        }
        if (side != 0) { // the twins stay in no leaf, but in the list of objects
            copy(side, kept, end);
        }
        return kept;
    }

    /** Copies places {@code [start, end)} of set {@code side} to the same places of set 0. */
    private void copy(int side, int start, int end) {
        System.arraycopy(orders[side], start, orders[0], start, end - start);
        System.arraycopy(objectBoxes[side], 6 * start, objectBoxes[0], 6 * start, 6 * (end - start));
    }

    /** The extent of places {@code [start, end)} of set {@code side}, by one pass over them. */
    private float[] measure(int side, int start, int end) {
        float[] extent = new float[EXTENT];
        setEmpty(extent, 0);
        for (int i = start; i < end; i++) {
            add(extent, 0, objectBoxes[side], 6 * i);
        }
        return extent;
    }

    /** The axis along which the centres of {@code extent} spread most, or −1 if they all coincide. */
    private static int widestAxis(float[] extent) {
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

    /** Grows the extent at {@code extent[at ..]} by the object whose box is {@code box[b .. b+5]}. */
    private static void add(float[] extent, int at, float[] box, int b) {
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

    /** Grows the extent at {@code extent[at ..]} by the extent at {@code other[o ..]}. */
    private static void union(float[] extent, int at, float[] other, int o) {
        for (int k = 0; k < EXTENT; k++) {
            boolean isMin = k % 6 < 3;
            extent[at + k] = isMin ? Math.min(extent[at + k], other[o + k]) : Math.max(extent[at + k], other[o + k]);
        }
    }

    /** Makes the extent at {@code extent[at ..]} empty: it grows into any it is grown by. */
    private static void setEmpty(float[] extent, int at) {
        for (int k = 0; k < EXTENT; k++) {
            extent[at + k] = k % 6 < 3 ? Float.POSITIVE_INFINITY : Float.NEGATIVE_INFINITY;
        }
    }

    private static boolean isFinite(float[] box, int at) {
        for (int k = 0; k < 6; k++) {
            if (!Float.isFinite(box[at + k])) {
                return false;
            }
        }
        return true;
    }

    /** The surface area of the box at {@code box[at .. at+5]}. */
    private static float area(float[] box, int at) {
        float dx = box[at + 3] - box[at];
        float dy = box[at + 4] - box[at + 1];
        float dz = box[at + 5] - box[at + 2];
        return 2 * (dx * dy + dy * dz + dz * dx);
    }
}
