package rtd.accel;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveTask;
import java.util.function.IntConsumer;
import java.util.stream.IntStream;
import rtd.geometry.IGeometry;

/**
 * Builds the tree of a {@link Bvh} top-down with the binned surface area heuristic (SAH).
 *
 * <p>At each node the objects' centres are sorted into {@value #BINS} bins along the axis where
 * they spread most; of the splits between bins, the one with the lowest expected cost wins,
 * where a child's cost is its box's surface area (how likely a ray passes through it) times
 * its object count. A node becomes a leaf when no split is cheaper than testing its objects.
 *
 * <p>Large subtrees are built in parallel, and the nodes of very many objects near the root
 * bin and partition their objects in chunks side by side ({@link ChunkedPasses}). The tree does
 * not depend on the number of threads: each subtree owns a range of node numbers reserved in
 * advance (a subtree of n objects needs at most 2n − 1 nodes), the chunks depend only on the
 * node, and at the end the used nodes are numbered anew, depth first ({@link Compaction}).
 */
final class BvhBuilder {

    private static final int BINS = SahBins.COUNT;
    private static final int MAX_LEAF_SIZE = 16;
    /** Past this depth the builder halves by count, which bounds the depth for any input. */
    private static final int MAX_SAH_DEPTH = 48;
    /**
     * The cost of visiting a node, counted in intersection tests. Measured on the million-sphere
     * benchmark: 4 (with leaves of up to 16) rendered in 1.8 s where 1 took 3.2 s.
     */
    private static final float TRAVERSAL_COST = 4f;
    /**
     * Subtrees with fewer objects are built on the thread that reached them, and scenes with
     * fewer objects on the calling thread alone ({@link Bvh#build}).
     */
    static final int PARALLEL_THRESHOLD = 20_000;
    /**
     * Nodes with at least this many objects measure, bin and partition them in chunks
     * ({@link ChunkedPasses}), on any number of threads, so that the tree is the same for any.
     */
    private static final int CHUNKED_THRESHOLD = 4 * ChunkedPasses.CHUNK;
    private static final int INNER = Bvh.INNER;

    private final List<IGeometry> objects;
    /** The objects with a finite box, which the tree holds: {@code order[0, count)}. */
    private int count;
    /** The objects without one (planes), in file order: {@code order[count, objects.size())}. */
    private int[] unbounded;
    /*
     * The objects' boxes, kept in the order of `order` and swapped along with it, so that every
     * pass over a node's objects reads memory front to back (random reads into these arrays
     * made building a million objects ten times slower). An object's centre, by which it is
     * sorted, is computed from its box where needed: fewer numbers to move than to keep.
     */
    /** Places in {@code objects}, reordered so that each node's objects are adjacent. */
    private final int[] order;
    /** Per place in {@code order}: the object's box, min x, y, z, max x, y, z. */
    private final float[] boxes;
    /** Node boxes and contents as in {@link Bvh}, at the reserved node numbers. */
    private final float[] bounds;
    private final int[] nodes;
    private final ForkJoinPool pool;
    /** The passes over nodes of at least {@link #CHUNKED_THRESHOLD} objects; {@code null} if there are none. */
    private final ChunkedPasses chunked;
    private int maxDepth;

    /**
     * A builder for the scene's {@code objects}, that works on {@code pool}, or on the calling
     * thread alone if it is {@code null}. Each object's box is measured once; the objects
     * without a finite one are kept apart ({@link #unbounded}).
     */
    BvhBuilder(List<IGeometry> objects, ForkJoinPool pool) {
        this.objects = objects;
        this.count = objects.size();
        this.pool = pool;
        this.order = new int[count];
        this.boxes = new float[6 * count];
        if (pool == null) { // no lambda either: its first use costs more than a small scene's whole build
            for (int i = 0; i < count; i++) {
                measureObject(i);
            }
        } else {
            forEach(this::measureObject);
        }
        setUnboundedApart();
        int capacity = Math.max(1, 2 * count - 1);
        this.bounds = new float[6 * capacity];
        this.nodes = new int[2 * capacity];
        this.chunked = count >= CHUNKED_THRESHOLD ? new ChunkedPasses(order, boxes, count, pool) : null;
    }

    /** Whether this builder works on a pool of threads. */
    boolean parallel() {
        return pool != null;
    }

    /** Runs {@code action} for 0 to count − 1: in parallel on the pool, or in order on this thread. */
    void forEach(IntConsumer action) {
        if (pool == null) {
            for (int i = 0; i < count; i++) {
                action.accept(i);
            }
        } else {
            pool.submit(() -> IntStream.range(0, count).parallel().forEach(action)).join();
        }
    }

    /**
     * Moves the objects whose box is not finite behind the others, each group in file order,
     * and leaves {@link #count} at the number of the others.
     */
    private void setUnboundedApart() {
        int kept = 0;
        int[] apart = new int[0];
        for (int i = 0; i < count; i++) {
            if (isFinite(i)) {
                if (kept != i) {
                    order[kept] = order[i];
                    System.arraycopy(boxes, 6 * i, boxes, 6 * kept, 6);
                }
                kept++;
            } else {
                apart = Arrays.copyOf(apart, apart.length + 1);
                apart[apart.length - 1] = order[i];
            }
        }
        System.arraycopy(apart, 0, order, kept, apart.length);
        unbounded = apart;
        count = kept;
    }

    private boolean isFinite(int i) {
        for (int k = 0; k < 6; k++) {
            if (!Float.isFinite(boxes[6 * i + k])) {
                return false;
            }
        }
        return true;
    }

    /** The places in the file of the objects without a finite box, in file order. */
    int[] unbounded() {
        return unbounded;
    }

    /** The number of objects in the tree. */
    int count() {
        return count;
    }

    /** Puts object {@code i}'s box in place {@code i}. */
    private void measureObject(int i) {
        objects.get(i).putBounds(boxes, 6 * i);
        order[i] = i;
    }

    /** Builds the tree; afterwards {@link #order} and {@link #boxes} are in leaf order. */
    void build() {
        maxDepth = pool == null
                ? buildNode(0, 1, 0, count, 0, null, new SahBins())
                : pool.invoke(new Subtree(0, 1, 0, count, 0, null));
    }

    /** The objects' places in the file, in the order of the tree's leaves ({@link #count} of them). */
    int[] order() {
        return order;
    }

    /** The objects' boxes in leaf order, six floats each. */
    float[] boxes() {
        return boxes;
    }

    /** The depth of the deepest leaf. */
    int maxDepth() {
        return maxDepth;
    }

    /** The node boxes, with numbers reserved but not all used. */
    float[] bounds() {
        return bounds;
    }

    /** The node contents, with numbers reserved but not all used. */
    int[] nodes() {
        return nodes;
    }

    /** A large subtree, built as a task of its own so that another thread can take it. */
    private final class Subtree extends RecursiveTask<Integer> {
        private static final long serialVersionUID = 1L;
        private final int node;
        private final int free;
        private final int start;
        private final int end;
        private final int depth;
        private final Extent extent;

        Subtree(int node, int free, int start, int end, int depth, Extent extent) {
            this.node = node;
            this.free = free;
            this.start = start;
            this.end = end;
            this.depth = depth;
            this.extent = extent;
        }

        @Override
        protected Integer compute() {
            return buildNode(node, free, start, end, depth, extent, new SahBins());
        }
    }

    /**
     * Builds the node numbered {@code node} over {@code order[start, end)}; its descendants get
     * the numbers from {@code free} on, at most {@code 2(end − start) − 2} of them. The node's
     * {@code extent} comes from its parent's bins, or is {@code null} and measured here.
     * Answers the subtree's depth.
     */
    private int buildNode(int node, int free, int start, int end, int depth, Extent extent, SahBins bins) {
        Extent known = extent != null ? extent : measure(start, end);
        System.arraycopy(known.box(), 0, bounds, 6 * node, 6);
        if (end - start > 1 && widestAxis(known.centres()) < 0) {
            end = withoutTwins(start, end);
        }
        int n = end - start;
        Split split = n <= 1 ? null : depth < MAX_SAH_DEPTH ? splitBySah(known, start, end, bins) : splitByCount(start, end);
        if (split == null) {
            nodes[2 * node] = start;
            nodes[2 * node + 1] = n;
            return depth;
        }
        int left = free;
        nodes[2 * node] = left;
        nodes[2 * node + 1] = INNER;
        int leftCount = split.middle() - start;
        int rightFree = free + 2 * leftCount;
        if (pool == null || n < PARALLEL_THRESHOLD) { // fork() outside a pool would use the common pool
            return Math.max(buildNode(left, free + 2, start, split.middle(), depth + 1, split.left(), bins),
                    buildNode(left + 1, rightFree, split.middle(), end, depth + 1, split.right(), bins));
        }
        Subtree leftTree = new Subtree(left, free + 2, start, split.middle(), depth + 1, split.left());
        leftTree.fork();
        int rightDepth = buildNode(left + 1, rightFree, split.middle(), end, depth + 1, split.right(), bins);
        return Math.max(leftTree.join(), rightDepth);
    }

    /** The extent of {@code order[start, end)}, by one pass over the objects. */
    private Extent measure(int start, int end) {
        if (end - start >= CHUNKED_THRESHOLD) {
            return chunked.measure(start, end);
        }
        Extent extent = Extent.empty();
        for (int i = start; i < end; i++) {
            extent.add(boxes, 6 * i);
        }
        return extent;
    }

    /**
     * Finds the cheapest split by the SAH and partitions {@code order[start, end)} by it.
     * Returns {@code null} when a leaf is cheaper. Each child's box is the union of its bins',
     * and its box of centres is found by the partition: exactly what a pass over its objects
     * would measure.
     */
    private Split splitBySah(Extent extent, int start, int end, SahBins bins) {
        int n = end - start;
        float[] centreBox = extent.centres();
        int axis = widestAxis(centreBox);
        if (axis < 0) {
            return n > MAX_LEAF_SIZE ? splitByCount(start, end) : null; // all centres coincide
        }
        if (alwaysLeaf(n, extent)) {
            return null;
        }
        float lo = centreBox[axis];
        float scale = BINS / (centreBox[axis + 3] - lo);
        bins.clear();
        SahBins[] chunks = null;
        if (n >= CHUNKED_THRESHOLD) {
            chunks = chunked.bin(start, end, axis, lo, scale, bins);
        } else {
            bins.add(boxes, start, end, axis, lo, scale);
        }
        float[] costs = bins.splitCosts();
        float bestCost = Float.POSITIVE_INFINITY;
        int bestBin = -1;
        for (int split = 0; split < BINS - 1; split++) {
            if (costs[split] < bestCost) {
                bestCost = costs[split];
                bestBin = split;
            }
        }
        float leafCost = n;
        float splitCost = TRAVERSAL_COST + bestCost / SahBins.area(extent.box(), 0);
        if (splitCost >= leafCost && n <= MAX_LEAF_SIZE) {
            return null;
        }
        Extent left = bins.box(0, bestBin + 1);
        Extent right = bins.box(bestBin + 1, BINS);
        int middle = chunks != null
                ? chunked.partition(start, end, axis, lo, scale, bestBin, chunks, left, right)
                : partition(start, end, axis, bestBin, lo, scale, left, right);
        if (middle == start || middle == end) {
            return splitByCount(start, end);
        }
        return new Split(middle, left, right);
    }

    /**
     * Whether a node of {@code n} objects is a leaf whatever its bins: with no more objects than
     * a visit costs and a box of finite, nonzero area, a split costs at least
     * {@link #TRAVERSAL_COST} ≥ n, so {@link #splitBySah} would choose the leaf. Half the nodes
     * are this small, and need not be binned.
     */
    private static boolean alwaysLeaf(int n, Extent extent) {
        float area = SahBins.area(extent.box(), 0);
        return n <= TRAVERSAL_COST && area > 0 && area < Float.POSITIVE_INFINITY;
    }

    /**
     * Moves the objects of {@code order[start, end)} that are the twin of one before them in
     * the file ({@link IGeometry#sameTest}) to the back, and returns where they start: the tree
     * leaves them out. A twin reports the same hit as the first of its kind for every ray, and
     * on that tie the first in the file wins, so the twin never does. Only where all centres
     * coincide, the one place where many twins can gather and defeat the tree (a hundred
     * thousand copies of one sphere would all be tested by every ray that reaches them).
     */
    private int withoutTwins(int start, int end) {
        Arrays.sort(order, start, end); // file order, so that the first of each kind is kept
        Map<Object, Boolean> seen = new HashMap<>();
        int kept = start;
        for (int i = start; i < end; i++) {
            if (seen.putIfAbsent(objects.get(order[i]).sameTest(), Boolean.TRUE) == null) {
                int object = order[i];
                order[i] = order[kept];
                order[kept++] = object;
            }
        }
        refreshData(start, end);
        return kept;
    }

    /** Puts each object's box back at its place in {@code order[start, end)}. */
    private void refreshData(int start, int end) {
        for (int i = start; i < end; i++) {
            objects.get(order[i]).putBounds(boxes, 6 * i);
        }
    }

    /** The axis along which the centres spread most, or −1 if they all coincide. */
    private static int widestAxis(float[] centreBox) {
        int axis = -1;
        float widest = 0;
        for (int k = 0; k < 3; k++) {
            float spread = centreBox[k + 3] - centreBox[k];
            if (spread > widest) {
                widest = spread;
                axis = k;
            }
        }
        return axis;
    }

    /**
     * Moves the objects in bins {@code ≤ lastLeftBin} to the front; returns where the rest
     * start. Grows the boxes of centres of {@code left} and {@code right} by their objects'.
     */
    private int partition(int start, int end, int axis, int lastLeftBin, float lo, float scale, Extent left, Extent right) {
        CentreBox leftCentres = new CentreBox();
        CentreBox rightCentres = new CentreBox();
        int i = start;
        int j = end - 1;
        while (i <= j) {
            int at = 6 * i;
            if (SahBins.binOf((boxes[at + axis] + boxes[at + axis + 3]) * 0.5f, lo, scale) <= lastLeftBin) {
                leftCentres.add(boxes, at);
                i++;
            } else {
                rightCentres.add(boxes, at);
                swap(i, j);
                j--;
            }
        }
        leftCentres.growInto(left.centres());
        rightCentres.growInto(right.centres());
        return i;
    }

    /** Swaps the objects at places i and j of {@code order}, with their boxes. */
    private void swap(int i, int j) {
        int object = order[i];
        order[i] = order[j];
        order[j] = object;
        swapRange(boxes, 6 * i, 6 * j, 6);
    }

    private static void swapRange(float[] array, int a, int b, int length) {
        for (int k = 0; k < length; k++) {
            float value = array[a + k];
            array[a + k] = array[b + k];
            array[b + k] = value;
        }
    }

    /**
     * Splits in half by count, keeping the present order: a fallback for objects that the SAH
     * cannot separate (equal centres) and for very deep trees. The children measure their
     * extents themselves.
     */
    private static Split splitByCount(int start, int end) {
        return end - start <= 1 ? null : new Split(start + (end - start) / 2, null, null);
    }

    /** Where a node's objects divide ({@code order[middle]} is the right child's first), and the children's extents, if known. */
    private record Split(int middle, Extent left, Extent right) {
    }

}
