package rtd.accel;

/**
 * The box around the centres of the objects that a partition sends to one side, grown object by
 * object. Its six numbers are fields, not an array, so that the JIT keeps them in registers
 * while the partition runs (the object does not leave the loop): the partition finds the
 * children's boxes of centres almost for free, where bins would each need a second box.
 */
final class CentreBox {

    private float minX = Float.POSITIVE_INFINITY;
    private float minY = Float.POSITIVE_INFINITY;
    private float minZ = Float.POSITIVE_INFINITY;
    private float maxX = Float.NEGATIVE_INFINITY;
    private float maxY = Float.NEGATIVE_INFINITY;
    private float maxZ = Float.NEGATIVE_INFINITY;

    /** Adds the centre of the box at {@code boxes[at .. at+5]}, {@code (min + max) · 0.5} as {@link Extent} computes it. */
    void add(float[] boxes, int at) {
        float x = (boxes[at] + boxes[at + 3]) * 0.5f;
        float y = (boxes[at + 1] + boxes[at + 4]) * 0.5f;
        float z = (boxes[at + 2] + boxes[at + 5]) * 0.5f;
        minX = FastMath.min(minX, x);
        minY = FastMath.min(minY, y);
        minZ = FastMath.min(minZ, z);
        maxX = FastMath.max(maxX, x);
        maxY = FastMath.max(maxY, y);
        maxZ = FastMath.max(maxZ, z);
    }

    /** Grows the box {@code box} (min x, y, z, max x, y, z) to hold this one. */
    void growInto(float[] box) {
        box[0] = FastMath.min(box[0], minX);
        box[1] = FastMath.min(box[1], minY);
        box[2] = FastMath.min(box[2], minZ);
        box[3] = FastMath.max(box[3], maxX);
        box[4] = FastMath.max(box[4], maxY);
        box[5] = FastMath.max(box[5], maxZ);
    }
}
