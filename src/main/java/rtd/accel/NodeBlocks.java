package rtd.accel;

import java.util.Arrays;

/**
 * The nodes of a tree that a {@link BvhBuilder} is building, in the builder's own layout (box at
 * {@code 6i}, contents at {@code 2i}; {@link Compaction} copies them into {@link Bvh}'s, 8 floats a
 * node), in arrays that grow as the tree does.
 *
 * <p>How many nodes a tree has is known only once it is built: up to 2n − 1 for n objects, but
 * fewer than n / 2 where leaves hold four objects or more, as the SAH makes them for spheres and
 * triangles. So the arrays start with room for n / 2 nodes, and double only if the tree needs it.
 */
final class NodeBlocks {

    /** The fewest nodes there is room for. */
    private static final int MIN_ROOM = 64;

    private float[] bounds;
    private int[] nodes;
    /** How many numbers are handed out; the root, 0, is the first. */
    private int handedOut = 1;

    /** The nodes of a new tree over {@code objects} objects, with the root's number handed out. */
    NodeBlocks(int objects) {
        int room = Math.max(MIN_ROOM, objects / 2);
        bounds = new float[6 * room];
        nodes = new int[2 * room];
    }

    /** Two new numbers in a row, for the children of an inner node; answers the first. */
    int pair() {
        int first = handedOut;
        handedOut += 2;
        if (2 * handedOut > nodes.length) {
            bounds = Arrays.copyOf(bounds, 2 * bounds.length);
            nodes = Arrays.copyOf(nodes, 2 * nodes.length);
        }
        return first;
    }

    /** Sets node {@code node}'s box to the six floats of {@code box}. */
    void setBox(int node, float[] box) {
        System.arraycopy(box, 0, bounds, 6 * node, 6);
    }

    /** Makes node {@code node} an inner node whose children are {@code firstChild} and {@code firstChild + 1}. */
    void setInner(int node, int firstChild) {
        nodes[2 * node] = firstChild;
        nodes[2 * node + 1] = Bvh.INNER;
    }

    /** Makes node {@code node} a leaf of {@code count} objects from place {@code first}. */
    void setLeaf(int node, int first, int count) {
        nodes[2 * node] = first;
        nodes[2 * node + 1] = count;
    }

    /** The first child of inner node {@code node}. */
    int firstChild(int node) {
        return nodes[2 * node];
    }

    /** The boxes, with room beyond the numbers handed out (no node points there). */
    float[] bounds() {
        return bounds;
    }

    /** The contents, as {@link #bounds}. */
    int[] nodes() {
        return nodes;
    }
}
