package rtd.accel;

import rtd.geometry.IGeometry;

/**
 * How far a box of a {@link Bvh} grows for a ray, so that no hit is lost to rounding: an
 * object's test may report a hit outside its box by a margin that grows with the distance the
 * ray has run ({@link IGeometry#bounds}, {@link Rounding}). A walk down the tree
 * knows a t beyond which the ray cannot be in a node (the tree's {@link #reach}, then each
 * parent's exit), and grows the node's children by their margin there ({@link #growth}).
 */
final class BoxGrowth {

    private BoxGrowth() {
    }

    /**
     * A t beyond which no object of the tree can report a hit, for a ray from {@code (x, y, z)}
     * with direction length {@code length}: a hit at t lies in the root's box grown by
     * {@code cone·t}, at most the box's farthest corner plus {@code 3·cone·t} from the origin
     * (summing over the axes), and {@code t·|R|} from it.
     */
    static float reach(Bvh bvh, float x, float y, float z, float length) {
        float[] root = bvh.boxes; // node 0
        double far = farthest(x, root[0], root[3]) + farthest(y, root[1], root[4]) + farthest(z, root[2], root[5]);
        double widest = KnownShapes.ROUNDING_CONE + root[Bvh.ROUNDING]; // the root's rounding is the largest
        float reach = (float) (far / (length * (1 - 3.0 * widest)) * (1 + 1e-6));
        return reach >= 0 ? reach : Float.POSITIVE_INFINITY; // NaN (a ray of no length): assume the worst
    }

    private static double farthest(double origin, double min, double max) {
        return Math.max(Math.abs(origin - min), Math.abs(origin - max));
    }

    /** {@code linear·L + min(ROUNDING_CONE·L, quadratic·L²)} of {@code node}, infinite if that is not a number. */
    static float growth(float[] boxes, int node, float distance) {
        int at = Bvh.BOX * node + Bvh.ROUNDING;
        float grow = boxes[at] * distance
                + Math.min(KnownShapes.ROUNDING_CONE * distance, boxes[at + 1] * distance * distance);
        return grow >= 0 ? grow : Float.POSITIVE_INFINITY;
    }
}
