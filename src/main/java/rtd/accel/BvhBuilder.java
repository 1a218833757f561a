package rtd.accel;

import java.util.ArrayDeque;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveTask;
import java.util.function.IntConsumer;
import java.util.stream.IntStream;
import rtd.geometry.IGeometry;

/**
 * Builds the tree of a {@link Bvh} top-down with the binned surface area heuristic (SAH).
 *
 * <p>Each node's objects are divided where the SAH expects rays to test the fewest objects, or
 * the node becomes a leaf when no split is cheaper than testing its objects: how the cost is
 * counted and the objects divided is the {@link SahSplitter}'s part; this class makes the nodes.
 *
 * <p>A node's objects are partitioned by copying them, in order, from one {@link ObjectArrays}
 * into the other; the children partition them back. Large subtrees are built in parallel, and
 * the nodes of very many objects near the root bin and partition their objects in chunks side
 * by side ({@link ChunkedPasses}). The tree does not depend on the number of threads: the
 * partition keeps the objects' order, each node is split by its own objects alone, and the
 * nodes, numbered as the threads happen to make them ({@link NodeBlocks}), are numbered anew
 * at the end, depth first ({@link Compaction}).
 */
final class BvhBuilder {

    /** Past this depth the builder halves by count, which bounds the depth for any input. */
    private static final int MAX_SAH_DEPTH = 48;
    /**
     * Subtrees with fewer objects are built on the thread that reached them, and scenes with
     * fewer objects on the calling thread alone ({@link Bvh#build}).
     */
    static final int PARALLEL_THRESHOLD = 20_000;
    /** Nodes with at least this many objects measure, bin and partition them in chunks ({@link ChunkedPasses}). */
    static final int CHUNKED_THRESHOLD = 8 * ChunkedPasses.CHUNK;

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
    private final ForkJoinPool pool;
    /** The passes over nodes of at least {@link #CHUNKED_THRESHOLD} objects. */
    private final ChunkedPasses chunked;
    /** How each node's objects divide, and the dividing. */
    private final SahSplitter splitter;
    private int maxDepth;

    /**
     * A builder for the scene's {@code objects}, that works on {@code pool}, or on the calling
     * thread alone if it is {@code null}. Each object's box is measured once ({@link ObjectBoxes}); the objects
     * without a finite one are kept apart ({@link #unbounded}).
     */
    BvhBuilder(List<IGeometry> objects, ForkJoinPool pool) {
        this.pool = pool;
        this.primary = ObjectArrays.of(objects.size());
        this.spare = ObjectArrays.of(objects.size());
        // the lambda is made only for a pool: a small scene's build, on this thread alone, makes none
        this.unbounded = ObjectBoxes.measure(objects, primary, pool == null ? null : action -> forEach(objects.size(), action));
        this.count = objects.size() - unbounded.length;
        this.tree = new NodeBlocks(count);
        this.chunked = new ChunkedPasses(pool);
        this.splitter = new SahSplitter(objects, primary, spare, chunked);
    }

    /** Whether this builder works on a pool of threads. */
    boolean parallel() {
        return pool != null;
    }

    /** Runs {@code action} for 0 to count − 1: in parallel on the pool, or in order on this thread. */
    void forEach(IntConsumer action) {
        forEach(count, action);
    }

    /** Runs {@code action} for 0 to {@code n} − 1: in parallel on the pool, or in order on this thread. */
    void forEach(int n, IntConsumer action) {
        if (pool == null) {
            for (int i = 0; i < n; i++) {
                action.accept(i);
            }
        } else {
            pool.submit(() -> IntStream.range(0, n).parallel().forEach(action)).join();
        }
    }

    /** The places in the file of the objects without a finite box, in file order. */
    int[] unbounded() {
        return unbounded;
    }

    /** The number of objects in the tree. */
    int count() {
        return count;
    }

    /** Builds the tree; afterwards {@link #order()} and {@link #boxes()} are in leaf order. */
    void build() {
        maxDepth = pool == null
                ? buildLarge(0, 0, count, 0, null, primary, new SahBins(), tree.newRun())
                : pool.invoke(new Subtree(0, 0, count, 0, null, primary));
    }

    /** The objects' places in the file, in the order of the tree's leaves ({@link #count} of them). */
    int[] order() {
        return primary.order();
    }

    /**
     * The second set of arrays, which the partitions no longer need once the tree is built: for
     * {@link LeafObjects} to pack its numbers into. New arrays would take new memory: the spare arrays stay alive anyway, until a concurrent mark finds them
     * dead, since the tasks of the build that point to them have reached the old generation.
     */
    ObjectArrays spare() {
        return spare;
    }

    /** The objects' boxes in leaf order, six floats each. */
    float[] boxes() {
        return primary.boxes();
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

    /** A large subtree, built as a task of its own so that another thread can take it. */
    private final class Subtree extends RecursiveTask<Integer> {
        private static final long serialVersionUID = 1L;
        private final int node;
        private final int start;
        private final int end;
        private final int depth;
        private final Extent extent;
        private final ObjectArrays data;

        Subtree(int node, int start, int end, int depth, Extent extent, ObjectArrays data) {
            this.node = node;
            this.start = start;
            this.end = end;
            this.depth = depth;
            this.extent = extent;
            this.data = data;
        }

        @Override
        protected Integer compute() {
            return buildLarge(node, start, end, depth, extent, data, new SahBins(), tree.newRun());
        }
    }

    /**
     * {@link #buildNode} for a node of any size: one of {@value #PARALLEL_THRESHOLD} objects or
     * more is built here, its children in parallel, its passes in chunks if it is larger still;
     * smaller ones go to {@link #buildNode}. A few dozen nodes take this path: kept apart, it
     * leaves the code that builds the other hundreds of thousands free of branches that only
     * the top of the tree takes, on which the JIT would compile it anew (one that is never
     * taken while the JIT watches is compiled as a trap).
     */
    private int buildLarge(int node, int start, int end, int depth, Extent extent, ObjectArrays data,
            SahBins bins, NodeBlocks.Run numbers) {
        if (end - start < PARALLEL_THRESHOLD) {
            return buildNode(node, start, end, depth, extent, data, bins, numbers);
        }
        Extent known = extent != null ? extent
                : end - start >= CHUNKED_THRESHOLD ? chunked.measure(data, start, end) : measure(data, start, end);
        tree.setBox(node, known.box());
        if (SahSplitter.widestAxis(known.centres()) < 0) {
            end = splitter.withoutTwins(data, start, end);
        }
        Split split = depth < MAX_SAH_DEPTH ? splitter.splitBySah(known, data, start, end, bins)
                : SahSplitter.splitByCount(data, start, end);
        if (split == null) {
            return leaf(node, start, end, depth, data);
        }
        int left = inner(node, numbers);
        int middle = split.middle();
        if (pool == null) {
            return Math.max(buildLarge(left, start, middle, depth + 1, split.left(), split.data(), bins, numbers),
                    buildLarge(left + 1, middle, end, depth + 1, split.right(), split.data(), bins, numbers));
        }
        Subtree leftTree = new Subtree(left, start, middle, depth + 1, split.left(), split.data());
        leftTree.fork();
        int rightDepth = buildLarge(left + 1, middle, end, depth + 1, split.right(), split.data(), bins, numbers);
        return Math.max(leftTree.join(), rightDepth);
    }

    /**
     * Builds the node numbered {@code node} over places {@code [start, end)} of {@code data}
     * (the primary or the spare arrays), with fewer than {@value #PARALLEL_THRESHOLD} objects,
     * on this thread; its descendants get their numbers from {@code numbers}. The node's
     * {@code extent} comes from its parent's bins, or is {@code null} and measured here.
     * Answers the subtree's depth.
     *
     * <p>The subtree's nodes are built in a loop over a stack of those waiting, not by
     * recursion: the JIT compiles a loop early, while it runs, and a recursive method that it
     * inlines into itself is a long compilation, during which the build runs slower code.
     */
    private int buildNode(int node, int start, int end, int depth, Extent extent, ObjectArrays data,
            SahBins bins, NodeBlocks.Run numbers) {
        ArrayDeque<Pending> waiting = new ArrayDeque<>();
        waiting.push(new Pending(node, start, end, depth, extent, data));
        int deepest = depth;
        while (!waiting.isEmpty()) {
            Pending next = waiting.pop();
            Split split = split(next, bins, numbers);
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
    private Split split(Pending waiting, SahBins bins, NodeBlocks.Run numbers) {
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
            leaf(waiting.node(), start, end, waiting.depth(), data);
        } else {
            inner(waiting.node(), numbers);
        }
        return split;
    }

    /** A node that waits to be built, with what {@link #buildNode} would be called with. */
    private record Pending(int node, int start, int end, int depth, Extent extent, ObjectArrays data) {
    }

    /** Makes node {@code node} the leaf of places {@code [start, end)}, whose objects go to the primary arrays. */
    private int leaf(int node, int start, int end, int depth, ObjectArrays data) {
        if (data != primary) {
            data.copy(start, end, primary);
        }
        tree.setLeaf(node, start, end - start);
        return depth;
    }

    /** Makes node {@code node} an inner node with two new children from {@code numbers}; answers the first. */
    private int inner(int node, NodeBlocks.Run numbers) {
        int first = numbers.pair();
        tree.setInner(node, first);
        return first;
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

