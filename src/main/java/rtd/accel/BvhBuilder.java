package rtd.accel;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveTask;
import java.util.stream.IntStream;
import rtd.camera.ICamera;
import rtd.geometry.BoundingBox;
import rtd.geometry.IGeometry;
import rtd.math.Vector3f;
import rtd.scene.Color;

/**
 * Builds a {@link Bvh} top-down with the binned surface area heuristic (SAH).
 *
 * <p>At each node the objects' centres are sorted into {@value #BINS} bins along the axis where
 * they spread most; of the splits between bins, the one with the lowest expected cost wins,
 * where a child's cost is its box's surface area (how likely a ray passes through it) times
 * its object count. A node becomes a leaf when no split is cheaper than testing its objects.
 *
 * <p>Large subtrees are built in parallel. The tree does not depend on the number of threads:
 * each subtree owns a range of node numbers reserved in advance (a subtree of n objects needs
 * at most 2n − 1 nodes), and at the end the used nodes are numbered anew, depth first.
 */
final class BvhBuilder {

    private static final int BINS = 16;
    private static final int MAX_LEAF_SIZE = 16;
    /** Past this depth the builder halves by count, which bounds the depth for any input. */
    private static final int MAX_SAH_DEPTH = 48;
    /**
     * The cost of visiting a node, counted in intersection tests. Measured on the million-sphere
     * benchmark: 4 (with leaves of up to 16) rendered in 1.8 s where 1 took 3.2 s.
     */
    private static final float TRAVERSAL_COST = 4f;
    /** Subtrees with fewer objects are built on the thread that reached them. */
    private static final int PARALLEL_THRESHOLD = 20_000;
    private static final int INNER = Bvh.INNER;

    private final List<IGeometry> objects;
    private final int count;
    /*
     * The objects' data, kept in the order of `order` and swapped along with it, so that every
     * pass over a node's objects reads memory front to back (random reads into these arrays
     * made building a million objects ten times slower).
     */
    /** Object indices in the scene file, reordered so that each node's objects are adjacent. */
    private final int[] order;
    /** Per place in {@code order}: the object's box, min x, y, z, max x, y, z. */
    private final float[] boxes;
    /** Per place in {@code order}: the centre of the object's box, x, y, z. */
    private final float[] centres;
    /** Node boxes and contents as in {@link Bvh}, at the reserved node numbers. */
    private final float[] bounds;
    private final int[] nodes;
    private final ForkJoinPool pool;

    BvhBuilder(List<IGeometry> objects, ICamera camera, ForkJoinPool pool) {
        this.objects = objects;
        this.count = objects.size();
        this.pool = pool;
        this.order = new int[count];
        this.boxes = new float[6 * count];
        this.centres = new float[3 * count];
        pool.submit(() -> IntStream.range(0, count).parallel().forEach(i -> {
            BoundingBox box = objects.get(i).bounds(camera);
            put(boxes, 6 * i, box.min());
            put(boxes, 6 * i + 3, box.max());
            put(centres, 3 * i, box.centre());
            order[i] = i;
        })).join();
        int capacity = Math.max(1, 2 * count - 1);
        this.bounds = new float[6 * capacity];
        this.nodes = new int[2 * capacity];
    }

    private static void put(float[] array, int at, Vector3f v) {
        array[at] = v.x();
        array[at + 1] = v.y();
        array[at + 2] = v.z();
    }

    Bvh build(Color ambient) {
        int maxDepth = pool.invoke(new Subtree(0, 1, 0, count, 0));
        IGeometry[] sorted = new IGeometry[count];
        for (int i = 0; i < count; i++) {
            sorted[i] = objects.get(order[i]);
        }
        return new Compaction(bounds, nodes).run(sorted, boxes, order, maxDepth, ambient);
    }

    /** Builds the subtree of one node; answers its depth. */
    private final class Subtree extends RecursiveTask<Integer> {
        private static final long serialVersionUID = 1L;
        private final int node;
        private final int free;
        private final int start;
        private final int end;
        private final int depth;

        /**
         * The node numbered {@code node} over {@code order[start, end)}; its descendants get
         * the numbers from {@code free} on, at most {@code 2(end − start) − 2} of them.
         */
        Subtree(int node, int free, int start, int end, int depth) {
            this.node = node;
            this.free = free;
            this.start = start;
            this.end = end;
            this.depth = depth;
        }

        @Override
        protected Integer compute() {
            setBoundsOfObjects(node, start, end);
            int n = end - start;
            int middle = n <= 1 ? -1 : depth < MAX_SAH_DEPTH ? splitBySah(node, start, end) : splitByCount(start, end);
            if (middle < 0) {
                nodes[2 * node] = start;
                nodes[2 * node + 1] = n;
                return depth;
            }
            int left = free;
            nodes[2 * node] = left;
            nodes[2 * node + 1] = INNER;
            int leftCount = middle - start;
            Subtree leftTree = new Subtree(left, free + 2, start, middle, depth + 1);
            Subtree rightTree = new Subtree(left + 1, free + 2 * leftCount, middle, end, depth + 1);
            if (n < PARALLEL_THRESHOLD) {
                return Math.max(leftTree.compute(), rightTree.compute());
            }
            leftTree.fork();
            int rightDepth = rightTree.compute();
            return Math.max(leftTree.join(), rightDepth);
        }
    }

    private void setBoundsOfObjects(int node, int start, int end) {
        float[] box = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
            Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        for (int i = start; i < end; i++) {
            int o = 6 * i;
            for (int k = 0; k < 3; k++) {
                box[k] = FastMath.min(box[k], boxes[o + k]);
                box[k + 3] = FastMath.max(box[k + 3], boxes[o + k + 3]);
            }
        }
        System.arraycopy(box, 0, bounds, 6 * node, 6);
    }

    /**
     * Finds the cheapest split by the SAH and partitions {@code order[start, end)} by it.
     * Returns the index where the right part starts, or −1 when a leaf is cheaper.
     */
    private int splitBySah(int node, int start, int end) {
        int n = end - start;
        float[] lo = new float[3];
        float[] hi = new float[3];
        centreBounds(start, end, lo, hi);
        int axis = widestAxis(lo, hi);
        if (axis < 0) {
            return n > MAX_LEAF_SIZE ? splitByCount(start, end) : -1; // all centres coincide
        }
        SahBins bins = new SahBins(BINS);
        float scale = BINS / (hi[axis] - lo[axis]);
        for (int i = start; i < end; i++) {
            bins.add(binOf(centres[3 * i + axis], lo[axis], scale), boxes, 6 * i);
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
        float splitCost = TRAVERSAL_COST + bestCost / SahBins.area(bounds, 6 * node);
        if (splitCost >= leafCost && n <= MAX_LEAF_SIZE) {
            return -1;
        }
        int middle = partition(start, end, axis, bestBin, lo[axis], scale);
        return middle == start || middle == end ? splitByCount(start, end) : middle;
    }

    private void centreBounds(int start, int end, float[] lo, float[] hi) {
        Arrays.fill(lo, Float.POSITIVE_INFINITY);
        Arrays.fill(hi, Float.NEGATIVE_INFINITY);
        for (int i = start; i < end; i++) {
            int c = 3 * i;
            for (int k = 0; k < 3; k++) {
                lo[k] = FastMath.min(lo[k], centres[c + k]);
                hi[k] = FastMath.max(hi[k], centres[c + k]);
            }
        }
    }

    /** The axis along which the centres spread most, or −1 if they all coincide. */
    private static int widestAxis(float[] lo, float[] hi) {
        int axis = -1;
        float widest = 0;
        for (int k = 0; k < 3; k++) {
            if (hi[k] - lo[k] > widest) {
                widest = hi[k] - lo[k];
                axis = k;
            }
        }
        return axis;
    }

    private static int binOf(float centre, float lo, float scale) {
        int bin = (int) ((centre - lo) * scale);
        return Math.min(BINS - 1, Math.max(0, bin));
    }

    /** Moves the objects in bins {@code ≤ lastLeftBin} to the front; returns where the rest start. */
    private int partition(int start, int end, int axis, int lastLeftBin, float lo, float scale) {
        int i = start;
        int j = end - 1;
        while (i <= j) {
            if (binOf(centres[3 * i + axis], lo, scale) <= lastLeftBin) {
                i++;
            } else {
                swap(i, j);
                j--;
            }
        }
        return i;
    }

    /** Swaps the objects at places i and j of {@code order}, with their data. */
    private void swap(int i, int j) {
        int object = order[i];
        order[i] = order[j];
        order[j] = object;
        swapRange(boxes, 6 * i, 6 * j, 6);
        swapRange(centres, 3 * i, 3 * j, 3);
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
     * cannot separate (equal centres) and for very deep trees.
     */
    private int splitByCount(int start, int end) {
        return end - start <= 1 ? -1 : start + (end - start) / 2;
    }

}
