package rtd.accel;

/**
 * Numbers the nodes of a freshly built tree anew, depth first from the root, leaving out the
 * numbers that {@link BvhBuilder} reserved but did not use. The result depends only on the
 * tree, and a ray's path through it reads memory mostly forwards. The boxes are copied with room
 * for each node's growth after them ({@link Bvh#BOX} floats a node), which {@link Bvh} fills in.
 */
final class Compaction {

    private final float[] oldBounds;
    private final int[] oldNodes;
    private final float[] boxes;
    private final int[] nodes;
    private int used;

    Compaction(float[] oldBounds, int[] oldNodes) {
        this.oldBounds = oldBounds;
        this.oldNodes = oldNodes;
        int count = count(0);
        boxes = new float[Bvh.BOX * count];
        nodes = new int[2 * count];
        used = 1;
        copy(0, 0);
    }

    /** The nodes of the subtree under old node {@code node}, itself included. */
    private int count(int node) {
        return oldNodes[2 * node + 1] != Bvh.INNER ? 1 : 1 + count(oldNodes[2 * node]) + count(oldNodes[2 * node] + 1);
    }

    /** The node boxes, renumbered, {@link Bvh#BOX} floats a node, the last two left for the growth. */
    float[] boxes() {
        return boxes;
    }

    /** The node contents, renumbered. */
    int[] nodes() {
        return nodes;
    }

    /** Copies old node {@code from} to new number {@code to}, and its children after it. */
    private void copy(int from, int to) {
        System.arraycopy(oldBounds, 6 * from, boxes, Bvh.BOX * to, 6);
        nodes[2 * to + 1] = oldNodes[2 * from + 1];
        if (oldNodes[2 * from + 1] != Bvh.INNER) {
            nodes[2 * to] = oldNodes[2 * from];
            return;
        }
        int children = used;
        used += 2;
        nodes[2 * to] = children;
        copy(oldNodes[2 * from], children);
        copy(oldNodes[2 * from] + 1, children + 1);
    }
}
