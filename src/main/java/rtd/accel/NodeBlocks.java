package rtd.accel;

import java.util.Arrays;

/**
 * The nodes of a tree that a {@link BvhBuilder} is building, in the builder's own layout (box at
 * {@code 6i}, contents at {@code 2i}; {@link Compaction} copies them into {@link Bvh}'s, 8 floats a
 * node), kept in blocks that are made as the tree grows.
 *
 * <p>How many nodes a tree has is known only once it is built: up to 2n − 1 for n objects, but
 * fewer than n / 2 where leaves hold four objects or more, as the SAH makes them for spheres and
 * triangles. Arrays reserved for 2n − 1 nodes would be about four times too large. So a block
 * holds n / 2 nodes (not rounded to a power of two, which would waste heap regions), and the tree
 * mostly fits in the first; more blocks are made only if it does not. The builder's threads take numbers in runs
 * ({@link Run}); the numbers then depend on which thread came first, but only the tree's shape
 * reaches {@link Bvh}, whose {@link Compaction} numbers the nodes anew.
 */
final class NodeBlocks {

    /** The fewest nodes in a block. */
    private static final int MIN_BLOCK = 64;
    /** The numbers a {@link Run} takes at a time: few enough that those a run leaves unused do not matter. */
    private static final int RUN_LENGTH = 128;

    /**
     * The blocks, made (and these lists grown) under the lock of {@link #handOut}. A thread
     * uses only the blocks of numbers handed out before it (through the lock or the fork of its
     * task); volatile, so that a list grown meanwhile by another thread is seen whole.
     */
    private volatile float[][] boundsBlocks = new float[1][];
    private volatile int[][] nodeBlocks = new int[1][];
    /** How many numbers are handed out (guarded by {@code this}); the root, 0, is the first. */
    private int handedOut = 1;
    /** Nodes per block. */
    private final int block;

    /** The blocks of a new tree over {@code objects} objects, with the root's number handed out. */
    NodeBlocks(int objects) {
        block = Math.max(MIN_BLOCK, objects / 2);
        makeBlocksUpTo(1);
    }

    /**
     * Hands out {@code count} numbers in a row and answers the first. Rare (once per run), so
     * a lock is cheap; it also makes the blocks it creates visible to the thread that takes the
     * numbers next.
     */
    private synchronized int handOut(int count) {
        int first = handedOut;
        handedOut += count;
        makeBlocksUpTo(handedOut);
        return first;
    }

    /** Makes the blocks for numbers up to {@code nodes}, in new lists that are then published whole. */
    private void makeBlocksUpTo(int nodes) {
        int blocks = (nodes - 1) / block + 1;
        if (blocks <= boundsBlocks.length && boundsBlocks[blocks - 1] != null) {
            return;
        }
        float[][] newBounds = Arrays.copyOf(boundsBlocks, Math.max(blocks, boundsBlocks.length));
        int[][] newNodes = Arrays.copyOf(nodeBlocks, newBounds.length);
        for (int b = 0; b < blocks; b++) {
            if (newBounds[b] == null) {
                newBounds[b] = new float[6 * block];
                newNodes[b] = new int[2 * block];
            }
        }
        boundsBlocks = newBounds;
        nodeBlocks = newNodes;
    }

    /** The block of node {@code node}: almost always the first, known without a division. */
    private int blockOf(int node) {
        return node < block ? 0 : node / block;
    }

    /** Sets node {@code node}'s box to the six floats of {@code box}. */
    void setBox(int node, float[] box) {
        int b = blockOf(node);
        System.arraycopy(box, 0, boundsBlocks[b], 6 * (node - b * block), 6);
    }

    /** Makes node {@code node} an inner node whose children are {@code firstChild} and {@code firstChild + 1}. */
    void setInner(int node, int firstChild) {
        setContents(node, firstChild, Bvh.INNER);
    }

    /** Makes node {@code node} a leaf of {@code count} objects from place {@code first}. */
    void setLeaf(int node, int first, int count) {
        setContents(node, first, count);
    }

    private void setContents(int node, int first, int second) {
        int b = blockOf(node);
        int at = 2 * (node - b * block);
        nodeBlocks[b][at] = first;
        nodeBlocks[b][at + 1] = second;
    }

    /** The first child of inner node {@code node}. */
    int firstChild(int node) {
        int b = blockOf(node);
        return nodeBlocks[b][2 * (node - b * block)];
    }

    /**
     * The boxes of the numbers handed out, in one array as {@link Bvh} lays them out: the first
     * block itself if the tree fits in it, which is then longer than the numbers handed out
     * (a number without a node has a box of zeros, and no node points to it). Ask once, when
     * the tree is built: the blocks are let go.
     */
    float[] bounds() {
        float[] flat = boundsBlocks[0];
        if (handedOut > flat.length / 6) {
            flat = new float[6 * handedOut];
            for (int b = 0; b < boundsBlocks.length && boundsBlocks[b] != null; b++) {
                int from = b * block;
                System.arraycopy(boundsBlocks[b], 0, flat, 6 * from, 6 * Math.min(block, handedOut - from));
            }
        }
        boundsBlocks = null;
        return flat;
    }

    /** The contents of the numbers handed out, in one array as {@link Bvh} lays them out; as {@link #bounds}, once. */
    int[] nodes() {
        int[] flat = nodeBlocks[0];
        if (handedOut > flat.length / 2) {
            flat = new int[2 * handedOut];
            for (int b = 0; b < nodeBlocks.length && nodeBlocks[b] != null; b++) {
                int from = b * block;
                System.arraycopy(nodeBlocks[b], 0, flat, 2 * from, 2 * Math.min(block, handedOut - from));
            }
        }
        nodeBlocks = null;
        return flat;
    }

    /** A new run of numbers, for one thread: each task of the builder has its own. */
    Run newRun() {
        return new Run();
    }

    /**
     * Numbers for the children of one thread's nodes, taken from the blocks {@value #RUN_LENGTH}
     * at a time, so that the threads seldom meet at the lock.
     */
    final class Run {
        private int next;
        private int end;

        /** Two new numbers in a row, for the children of an inner node; answers the first. */
        int pair() {
            if (end - next < 2) {
                next = handOut(RUN_LENGTH);
                end = next + RUN_LENGTH;
            }
            int first = next;
            next += 2;
            return first;
        }
    }
}
