package rtd.accel;

import java.util.List;
import rtd.geometry.IGeometry;
import rtd.scene.Scene;

/**
 * A bounding volume hierarchy: a binary tree of boxes over the scene's objects, so that a ray
 * tests only the objects whose boxes it passes through, about log N instead of the N of
 * Listing 4.3. It is not in the paper; it is the usual way to make ray tracing fast. It answers
 * the same question as the paper's loop, "what does this ray hit?", for any ray
 * ({@link BvhTracer}), and knows nothing of colours.
 *
 * <p>The tree is stored flat, for speed: node {@code i} has its box in
 * {@code boxes[8i .. 8i+5]} (min x, y, z, max x, y, z), how much the box grows as a ray runs in
 * {@code boxes[8i+6 .. 8i+7]}, and two numbers in {@code nodes[2i], nodes[2i+1]}. An inner node
 * has {@code nodes[2i+1] == INNER} and its children at {@code nodes[2i]} and
 * {@code nodes[2i] + 1}; a leaf holds {@code nodes[2i+1]} objects starting at place
 * {@code nodes[2i]} of {@link #leaves}.
 *
 * <p>A node's box and growth lie side by side, and so do two children's: a walk that opens a
 * node reads both its children's from one stretch of 64 bytes, once the tree no longer fits in
 * the processor's nearest caches.
 *
 * <p>Objects without a box (planes) have no place in a tree of boxes: they stay beside it,
 * in {@link #unbounded}, and every ray tests them, as the paper's loop does.
 */
public final class Bvh {

    /** Marks an inner node in {@code nodes[2i+1]}, where a leaf has its object count. */
    static final int INNER = -1;

    /** The floats of a node in {@link #boxes}. */
    static final int BOX = 8;
    /** Where a node's linear rounding is among its {@link #BOX} floats; the quadratic one follows. */
    static final int ROUNDING = 6;

    /**
     * Each node's box, six floats, and how much it grows as a ray runs: the largest
     * {@link Rounding} of its objects, linear and quadratic; {@link #BOX} floats a node.
     */
    final float[] boxes;
    final int[] nodes;
    /** The tree's objects in leaf order. */
    final LeafObjects leaves;
    /** The objects without a box, in file order, and their places in the file. */
    final IGeometry[] unbounded;
    final int[] unboundedOrder;
    final int maxDepth;
    final List<IGeometry> objects;

    Bvh(float[] boxes, int[] nodes, LeafObjects leaves, int[] unboundedOrder, int maxDepth,
            List<IGeometry> objects) {
        this.boxes = boxes;
        this.nodes = nodes;
        this.leaves = leaves;
        this.unboundedOrder = unboundedOrder;
        this.unbounded = new IGeometry[unboundedOrder.length];
        for (int i = 0; i < unbounded.length; i++) {
            unbounded[i] = objects.get(unboundedOrder[i]);
        }
        this.maxDepth = maxDepth;
        this.objects = objects;
    }

    /** Builds the hierarchy for {@code scene}, on this thread. */
    public static Bvh build(Scene scene) {
        return new BvhBuilder(scene.objects()).build();
    }

    /**
     * A hierarchy of one leaf, {@code leaves}, and the objects without a box beside it: no tree,
     * for a {@link ViewGrid}, which finds the objects a ray may hit in its own way; no walk reads
     * its root's box.
     */
    static Bvh oneLeaf(LeafObjects leaves, int[] unboundedOrder, List<IGeometry> objects) {
        return new Bvh(new float[BOX], new int[] {0, leaves.fileOrder.length}, leaves, unboundedOrder, 0, objects);
    }

    /**
     * Each node's largest rounding, from the leaves up: a node's children have larger numbers
     * than the node itself ({@link BvhBuilder}), so one pass backwards meets them first. The
     * objects' own are in {@code roundings}, in leaf order ({@link LeafObjects}).
     */
    static void putRoundings(float[] boxes, int[] nodes, float[] roundings) {
        for (int node = nodes.length / 2 - 1; node >= 0; node--) {
            int at = BOX * node + ROUNDING;
            if (nodes[2 * node + 1] == INNER) {
                int child = BOX * nodes[2 * node] + ROUNDING;
                boxes[at] = Math.max(boxes[child], boxes[child + BOX]);
                boxes[at + 1] = Math.max(boxes[child + 1], boxes[child + BOX + 1]);
            } else { // a leaf: the largest of its objects', linear and quadratic each
                int first = nodes[2 * node];
                for (int i = first; i < first + nodes[2 * node + 1]; i++) {
                    boxes[at] = Math.max(boxes[at], roundings[2 * i]);
                    boxes[at + 1] = Math.max(boxes[at + 1], roundings[2 * i + 1]);
                }
            }
        }
    }

    /**
     * A t beyond which no object of the tree can report a hit, for a ray from {@code (x, y, z)}
     * with direction length {@code length}: a hit at t lies in the root's box grown by
     * {@code cone·t}, at most the box's farthest corner plus {@code 3·cone·t} from the origin
     * (summing over the axes), and {@code t·|R|} from it.
     */
    float reach(float x, float y, float z, float length) {
        double far = farthest(x, boxes[0], boxes[3]) + farthest(y, boxes[1], boxes[4])
                + farthest(z, boxes[2], boxes[5]);
        double widest = KnownShapes.ROUNDING_CONE + boxes[ROUNDING]; // the root's rounding is the largest
        float reach = (float) (far / (length * (1 - 3.0 * widest)) * (1 + 1e-6));
        return reach >= 0 ? reach : Float.POSITIVE_INFINITY; // NaN (a ray of no length): assume the worst
    }

    private static double farthest(double origin, double min, double max) {
        return Math.max(Math.abs(origin - min), Math.abs(origin - max));
    }

    /**
     * How much to grow the boxes of {@code node}'s objects at a distance L the ray has run: their
     * {@link Rounding} there, {@code linear·L + min(ROUNDING_CONE·L, quadratic·L²)}, infinite if
     * that is not a number.
     */
    float growth(int node, float distance) {
        int at = BOX * node + ROUNDING;
        float grow = boxes[at] * distance
                + Math.min(KnownShapes.ROUNDING_CONE * distance, boxes[at + 1] * distance * distance);
        return grow >= 0 ? grow : Float.POSITIVE_INFINITY;
    }

    /** A new tracer that follows rays through this hierarchy; one per thread. */
    public BvhTracer newTracer() {
        return new BvhTracer(this);
    }

    /** The number of nodes in the tree. */
    public int nodeCount() {
        return hasTree() ? nodes.length / 2 : 0;
    }

    /** Whether there is a tree: whether the scene has objects with a box. */
    boolean hasTree() {
        return leaves.fileOrder.length > 0;
    }
}
