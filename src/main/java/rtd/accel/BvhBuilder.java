package rtd.accel;

import java.util.ArrayDeque;
import java.util.List;
import rtd.geometry.IGeometry;

/**
 * Builds the tree of a {@link Bvh} top-down with the binned surface area heuristic (SAH).
 *
 * <p>Each node's objects are divided where the SAH expects rays to test the fewest objects, or
 * the node becomes a leaf when no split is cheaper than testing its objects: how the cost is
 * counted and the objects divided is the {@link SahSplitter}'s part; this class makes the nodes.
 *
 * <p>A node's objects are partitioned by copying them, in order, from one {@link ObjectArrays}
 * into the other; the children partition them back. The nodes, numbered as they are made
 * ({@link NodeBlocks}), are numbered anew at the end, depth first ({@link Compaction}). It builds
 * on one thread: the hierarchy answers the rays the grids do not serve, and is built beside them.
 */
final class BvhBuilder {

    /** Past this depth the builder halves by count, which bounds the depth for any input. */
    private static final int MAX_SAH_DEPTH = 48;

    /** The objects with a finite box, which the tree holds: places {@code [0, count)} of {@link #primary}. */
    private final int count;
    /** The objects without one (planes), in file order: places {@code [count, objects.size())} of its order. */
    private final int[] unbounded;
    /**
     * The objects, where the leaves' objects end, in leaf order. Their boxes travel with them,
     * so that every pass over a node's objects reads memory front to back, not at random. An object's centre, by
     * which it is sorted, is computed from its box where needed: fewer numbers to move than to keep.
     */
    private final ObjectArrays primary;
    /** The second set of arrays, which the partitions copy into and back out of. */
    private final ObjectArrays spare;
    /** The nodes as they are made. */
    private final NodeBlocks tree;
    /** How each node's objects divide, and the dividing. */
    private final SahSplitter splitter;
    private int maxDepth;

    /**
     * A builder for the scene's {@code objects}. Each object's box is measured once
     * ({@link ObjectBoxes}); the objects without a finite one are kept apart ({@link #unbounded}).
     */
    BvhBuilder(List<IGeometry> objects) {
        this.primary = ObjectArrays.of(objects.size());
        this.spare = ObjectArrays.of(objects.size());
        this.unbounded = ObjectBoxes.measure(objects, primary);
        this.count = objects.size() - unbounded.length;
        this.tree = new NodeBlocks(count);
        this.splitter = new SahSplitter(objects, primary, spare);
    }

    /** The places in the file of the objects without a finite box, in file order. */
    int[] unbounded() {
        return unbounded;
    }

    /** The number of objects in the tree. */
    int count() {
        return count;
    }

    /** Builds the tree; afterwards {@link #order()} is in leaf order. */
    void build() {
        maxDepth = buildNode(0, 0, count, 0, null, primary, new SahBins());
    }

    /** The objects' places in the file, in the order of the tree's leaves ({@link #count} of them). */
    int[] order() {
        return primary.order();
    }

    /**
     * The second set of arrays, which the partitions no longer need once the tree is built: for
     * {@link LeafObjects} to pack its numbers into, instead of new arrays.
     */
    ObjectArrays spare() {
        return spare;
    }

    /** The depth of the deepest leaf. */
    int maxDepth() {
        return maxDepth;
    }

    /** The node boxes, with numbers not all used ({@link NodeBlocks#bounds}); asked once. */
    float[] bounds() {
        return tree.bounds();
    }

    /** The node contents, with numbers not all used ({@link NodeBlocks#nodes}); asked once. */
    int[] nodes() {
        return tree.nodes();
    }

    /**
     * Builds the node numbered {@code node} over places {@code [start, end)} of {@code data}
     * (the primary or the spare arrays). The node's {@code extent} comes from its parent's
     * bins, or is {@code null} and measured here.
     * Answers the subtree's depth.
     *
     * <p>The subtree's nodes are built in a loop over a stack of those waiting, not by
     * recursion: the JIT compiles a loop early, while it runs, and a recursive method that it
     * inlines into itself is a long compilation, during which the build runs slower code.
     */
    private int buildNode(int node, int start, int end, int depth, Extent extent, ObjectArrays data, SahBins bins) {
        ArrayDeque<Pending> waiting = new ArrayDeque<>();
        waiting.push(new Pending(node, start, end, depth, extent, data));
        int deepest = depth;
        while (!waiting.isEmpty()) {
            Pending next = waiting.pop();
            Split split = split(next, bins);
            if (split == null) {
                deepest = Math.max(deepest, next.depth());
                continue;
            }
            int left = tree.firstChild(next.node());
            waiting.push(new Pending(left + 1, split.middle(), split.end(), next.depth() + 1, split.right(),
                    split.data()));
            waiting.push(new Pending(left, next.start(), split.middle(), next.depth() + 1, split.left(), split.data()));
        }
        return deepest;
    }

    /**
     * Makes the {@code waiting} node a leaf (answers {@code null}) or an inner node, whose
     * children's objects are then divided as the answer says.
     */
    private Split split(Pending waiting, SahBins bins) {
        int start = waiting.start();
        int end = waiting.end();
        ObjectArrays data = waiting.data();
        Extent known = waiting.extent() != null ? waiting.extent() : measure(data, start, end);
        tree.setBox(waiting.node(), known.box());
        if (end - start > 1 && SahSplitter.widestAxis(known.centres()) < 0) {
            end = splitter.withoutTwins(data, start, end);
        }
        int n = end - start;
        Split split = n <= 1 ? null
                : waiting.depth() < MAX_SAH_DEPTH ? splitter.splitBySah(known, data, start, end, bins)
                : SahSplitter.splitByCount(data, start, end);
        if (split == null) {
            leaf(waiting.node(), start, end, data);
        } else {
            tree.setInner(waiting.node(), tree.pair());
        }
        return split;
    }

    /** A node that waits to be built, with what {@link #buildNode} would be called with. */
    private record Pending(int node, int start, int end, int depth, Extent extent, ObjectArrays data) {
    }

    /** Makes node {@code node} the leaf of places {@code [start, end)}, whose objects go to the primary arrays. */
    private void leaf(int node, int start, int end, ObjectArrays data) {
        if (data != primary) {
            data.copy(start, end, primary);
        }
        tree.setLeaf(node, start, end - start);
    }

    /** The extent of places {@code [start, end)} of {@code data}, by one pass over the objects. */
    private Extent measure(ObjectArrays data, int start, int end) {
        Extent extent = Extent.empty();
        for (int i = start; i < end; i++) {
            extent.add(data.boxes(), 6 * i);
        }
        return extent;
    }
}

