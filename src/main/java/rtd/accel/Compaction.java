package rtd.accel;

import java.util.Arrays;

/**
 * Numbers the nodes of a freshly built tree anew, depth first from the root, leaving out the
 * numbers that {@link BvhBuilder} reserved but did not use. The result depends only on the
 * tree, and a ray's path through it reads memory mostly forwards.
 */
final class Compaction {

    private final float[] oldBounds;
    private final int[] oldNodes;
    private float[] bounds;
    private int[] nodes;
    private int used;

    Compaction(float[] oldBounds, int[] oldNodes) {
        this.oldBounds = oldBounds;
        this.oldNodes = oldNodes;
        bounds = new float[oldBounds.length];
        nodes = new int[oldNodes.length];
        used = 1;
        copy(0, 0);
        bounds = Arrays.copyOf(bounds, 6 * used);
        nodes = Arrays.copyOf(nodes, 2 * used);
    }

    /** The node boxes, renumbered. */
    float[] bounds() {
        return bounds;
    }

    /** The node contents, renumbered. */
    int[] nodes() {
        return nodes;
    }

    /** Copies old node {@code from} to new number {@code to}, and its children after it. */
    private void copy(int from, int to) {
        System.arraycopy(oldBounds, 6 * from, bounds, 6 * to, 6);
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
