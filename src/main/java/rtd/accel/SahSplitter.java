package rtd.accel;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import rtd.geometry.IGeometry;

/**
 * Decides how a node of the {@link BvhBuilder}'s tree divides its objects, and divides them:
 * the binned surface area heuristic (SAH), and the two ways out where it cannot separate them.
 *
 * <p>The objects' centres are sorted into {@value #BINS} bins along the axis where they spread
 * most; of the splits between bins, the one with the lowest expected cost wins, where a child's
 * cost is its box's surface area (how likely a ray passes through it) times its object count.
 * A node becomes a leaf when no split is cheaper than testing its objects. The winner's
 * objects are copied, in order, from one {@link ObjectArrays} into the other ({@link Split}).
 * Where all centres coincide, the SAH has nothing to go by: twins of earlier objects are left
 * out ({@link #withoutTwins}) and the rest halved by count ({@link #splitByCount}), as in
 * very deep trees.
 */
final class SahSplitter {

    private static final int BINS = SahBins.COUNT;
    private static final int MAX_LEAF_SIZE = 16;
    /**
     * The cost of visiting a node, counted in intersection tests: 4, with leaves of up to 16, makes
     * shallow trees of full leaves, which a walk that waits for memory at each node favours.
     */
    private static final float TRAVERSAL_COST = 4f;
    /** What {@link #cheapestBin} answers when a leaf is cheaper than any split. */
    private static final int LEAF = Integer.MIN_VALUE;

    private final List<IGeometry> objects;
    /** The arrays where the leaves' objects end ({@link BvhBuilder#order}). */
    private final ObjectArrays primary;
    /** The second set of arrays, which the partitions copy into and back out of. */
    private final ObjectArrays spare;

    /** A splitter of the scene's {@code objects}, which partitions between {@code primary} and {@code spare}. */
    SahSplitter(List<IGeometry> objects, ObjectArrays primary, ObjectArrays spare) {
        this.objects = objects;
        this.primary = primary;
        this.spare = spare;
    }

    /**
     * Finds the cheapest split by the SAH and partitions places {@code [start, end)} of
     * {@code data} by it, into the other arrays. Returns {@code null} when a leaf is cheaper.
     * Each child's extent is the union of its bins', exactly what a pass over its objects would
     * measure.
     */
    Split splitBySah(Extent extent, ObjectArrays data, int start, int end, SahBins bins) {
        int n = end - start;
        float[] centreBox = extent.centres();
        int axis = widestAxis(centreBox);
        if (axis < 0) {
            return n > MAX_LEAF_SIZE ? splitByCount(data, start, end) : null; // all centres coincide
        }
        if (alwaysLeaf(n, extent)) {
            return null;
        }
        float lo = centreBox[axis];
        float scale = BINS / (centreBox[axis + 3] - lo);
        bins.clear();
        bins.add(data.boxes(), start, end, axis, lo, scale);
        int bestBin = cheapestBin(bins, extent, n);
        if (bestBin == LEAF) {
            return null;
        }
        int middle = start + bins.count(bestBin + 1);
        if (middle == start || middle == end) {
            return splitByCount(data, start, end);
        }
        ObjectArrays to = data == primary ? spare : primary;
        data.scatter(start, end, axis, lo, scale, bestBin, to, start, middle);
        return new Split(middle, end, bins.extent(0, bestBin + 1), bins.extent(bestBin + 1, BINS), to);
    }

    /**
     * The last bin of the left side of the cheapest split of filled {@code bins} (−1 if none
     * has two sides), or {@link #LEAF} if {@code n} objects cost less as a leaf.
     */
    private static int cheapestBin(SahBins bins, Extent extent, int n) {
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
        return splitCost >= leafCost && n <= MAX_LEAF_SIZE ? LEAF : bestBin;
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
     * Moves the objects of places {@code [start, end)} of {@code data} that are the twin of one before them in
     * the file ({@link KnownShapes#twinKey}) to the back, and returns where they start: the tree
     * leaves them out. A twin reports the same hit as the first of its kind for every ray, and
     * on that tie the first in the file wins, so the twin never does. Only where all centres
     * coincide, the one place where many twins can gather and defeat the tree (a hundred
     * thousand copies of one sphere would all be tested by every ray that reaches them).
     */
    int withoutTwins(ObjectArrays data, int start, int end) {
        int[] order = data.order();
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
        for (int i = start; i < end; i++) { // each object's box back at its place
            KnownShapes.putBox(objects.get(order[i]), data.boxes(), 6 * i);
        }
        if (data != primary) { // the twins stay in no leaf, but in the list of objects
            data.copy(kept, end, primary);
        }
        return kept;
    }

    /** The axis along which the centres spread most, or −1 if they all coincide. */
    static int widestAxis(float[] centreBox) {
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
     * Splits in half by count, keeping the present order: a fallback for objects that the SAH
     * cannot separate (equal centres) and for very deep trees. The children measure their
     * extents themselves.
     */
    static Split splitByCount(ObjectArrays data, int start, int end) {
        return end - start <= 1 ? null : new Split(start + (end - start) / 2, end, null, null, data);
    }
}
