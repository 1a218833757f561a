package rtd.accel;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import rtd.geometry.IGeometry;

/**
 * Builds the tree of a {@link Bvh} top-down with the binned surface area heuristic, as pbrt's BVH
 * does: a node's objects divide between the two {@link SahBins} where the expected cost is least,
 * along the axis where their centres spread most, or the node becomes a leaf when no split is
 * cheaper than testing its objects.
 *
 * <p>A node's objects are partitioned by copying them, in order, from one of two sets of arrays
 * into the other; the children partition them back, and a leaf's objects end in the first set.
 * Nodes are numbered depth first as they are made, a node's two children side by side, in the
 * {@link Bvh}'s layout. Where all centres of a node coincide the heuristic has nothing to go by:
 * the twins of earlier objects are left out ({@link #withoutTwins}) and the rest halved by count,
 * as in very deep trees. It builds on one thread, in a loop over the nodes waiting, which the JIT
 * compiles while it runs.
 */
final class BvhBuilder {

    private static final int MAX_LEAF_SIZE = 16;
    /** Past this depth nodes are halved by count, which bounds the depth for any input. */
    private static final int MAX_SAH_DEPTH = 48;
    /**
     * The cost of visiting a node, counted in intersection tests: with leaves of up to 16 it makes
     * shallow trees of full leaves, which a walk that waits for memory at each node favours.
     */
    private static final float TRAVERSAL_COST = 4f;

    private final List<IGeometry> objects;
    /** The objects with a finite box, which the tree holds: places {@code [0, count)}. */
    private final int count;
    /** The places in the file of the objects without one (planes), in file order. */
    private final int[] unbounded;
    /** Two sets of the objects' places in the file and their boxes (six floats a place); set 0 ends in leaf order. */
    private final int[][] orders;
    private final float[][] objectBoxes;
    private final SahBins bins = new SahBins();
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
        int[] apart = orders[1]; // free until the build
        int apartCount = 0;
        float[] box = new float[6];
        for (int f = 0; f < n; f++) {
            KnownShapes.putBox(objects.get(f), box, 0);
            if (ImageFootprint.isFinite(box)) {
                System.arraycopy(box, 0, objectBoxes[0], 6 * kept, 6);
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

    /** A node that waits to be built: its places in set {@code side}, and its extent if known. */
    private record Pending(int node, int start, int end, int depth, float[] extent, int side) {
    }

    /**
     * Builds the tree, and the {@link Bvh} of it: the objects packed in leaf order into the second set of arrays, which
     * the tree no longer needs ({@link LeafObjects}), and each node grown by its objects' rounding.
     */
    Bvh build() {
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
        // the first set's own array, unless objects without a box (planes) follow the tree's at its end
        int[] fileOrder = orders[0].length == count ? orders[0] : Arrays.copyOf(orders[0], count);
        float[] roundings = new float[2 * count];
        LeafObjects leaves = new LeafObjects(objects, fileOrder, orders[1], objectBoxes[1], null, roundings);
        Bvh.putRoundings(boxes, nodes, roundings);
        return new Bvh(boxes, nodes, leaves, unbounded, maxDepth, objects);
    }

    /** Makes the {@code waiting} node a leaf (answers null) or an inner node, and answers its children. */
    private Pending[] split(Pending waiting) {
        int start = waiting.start();
        int end = waiting.end();
        int side = waiting.side();
        float[] extent = waiting.extent() != null ? waiting.extent() : measure(side, start, end);
        System.arraycopy(extent, 0, boxes, Bvh.BOX * waiting.node(), 6);
        int axis = SahBins.widestAxis(extent);
        if (end - start > 1 && axis < 0) {
            end = withoutTwins(side, start, end);
        }
        Pending[] children;
        if (end - start <= 1) {
            children = null;
        } else if (waiting.depth() >= MAX_SAH_DEPTH) {
            children = byCount(waiting, end);
        } else if (axis < 0) { // all centres coincide
            children = end - start > MAX_LEAF_SIZE ? byCount(waiting, end) : null;
        } else {
            children = bySah(waiting, end, extent, axis);
        }
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
        float area = SahBins.area(extent);
        if (n <= TRAVERSAL_COST && area > 0 && area < Float.POSITIVE_INFINITY) {
            return null; // a split costs at least a visit, more than these objects' tests
        }
        float lo = extent[SahBins.CENTRES + axis];
        float scale = SahBins.COUNT / (extent[SahBins.CENTRES + axis + 3] - lo);
        bins.fill(objectBoxes[node.side()], start, end, axis, lo, scale);
        int bestBin = bins.cheapestSplit();
        if (TRAVERSAL_COST + bins.cost(bestBin) / area >= n && n <= MAX_LEAF_SIZE) {
            return null;
        }
        int middle = start + bins.count(bestBin + 1);
        if (middle == start || middle == end) {
            return byCount(node, end);
        }
        int to = 1 - node.side();
        scatter(node.side(), start, end, axis, lo, scale, bestBin, middle);
        int left = pair();
        return new Pending[] {new Pending(left, start, middle, node.depth() + 1, bins.extent(0, bestBin + 1), to),
                new Pending(left + 1, middle, end, node.depth() + 1, bins.extent(bestBin + 1, SahBins.COUNT), to)};
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
            int bin = SahBins.binOf((from[at + axis] + from[at + axis + 3]) * 0.5f, lo, scale);
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
        float[] extent = SahBins.empty();
        for (int i = start; i < end; i++) {
            SahBins.add(extent, 0, objectBoxes[side], 6 * i);
        }
        return extent;
    }
}
