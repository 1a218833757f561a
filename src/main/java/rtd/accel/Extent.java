package rtd.accel;

/**
 * What the {@link BvhBuilder} must know of a group of objects to split it: the box around
 * their boxes, and the box around their centres (along which axis they spread, and where the
 * bins lie). Both grow as objects are added; boxes are {min x, y, z, max x, y, z}, and an
 * object's centre is the centre of its box, {@code (min + max) · 0.5} in float as
 * {@link rtd.geometry.BoundingBox#centre} computes it.
 */
final class Extent {

    private final float[] box = new float[6];
    private final float[] centres = new float[6];

    private Extent() {
        setEmpty(box);
        setEmpty(centres);
    }

    /** An extent of no objects. */
    static Extent empty() {
        return new Extent();
    }

    /** Adds the object whose box is {@code boxes[at .. at+5]}. */
    void add(float[] boxes, int at) {
        for (int k = 0; k < 3; k++) {
            float min = boxes[at + k];
            float max = boxes[at + k + 3];
            box[k] = Math.min(box[k], min);
            box[k + 3] = Math.max(box[k + 3], max);
            float centre = (min + max) * 0.5f;
            centres[k] = Math.min(centres[k], centre);
            centres[k + 3] = Math.max(centres[k + 3], centre);
        }
    }

    /** Adds every object of {@code other}. */
    void add(Extent other) {
        grow(box, 0, other.box, 0);
        grow(centres, 0, other.centres, 0);
    }

    /** Grows the box at {@code box[at ..]} to hold the box at {@code other[otherAt ..]}. */
    static void grow(float[] box, int at, float[] other, int otherAt) {
        for (int k = 0; k < 3; k++) {
            box[at + k] = Math.min(box[at + k], other[otherAt + k]);
            box[at + k + 3] = Math.max(box[at + k + 3], other[otherAt + k + 3]);
        }
    }

    /** The box around the objects' boxes; the array itself, not a copy. */
    float[] box() {
        return box;
    }

    /** The box around the objects' centres; the array itself, not a copy. */
    float[] centres() {
        return centres;
    }

    /** Makes {@code box} the empty box, which grows into any box it is grown by. */
    static void setEmpty(float[] box) {
        setEmpty(box, 0);
    }

    /** Makes the box at {@code box[at .. at+5]} the empty box. */
    static void setEmpty(float[] box, int at) {
        box[at] = Float.POSITIVE_INFINITY;
        box[at + 1] = Float.POSITIVE_INFINITY;
        box[at + 2] = Float.POSITIVE_INFINITY;
        box[at + 3] = Float.NEGATIVE_INFINITY;
        box[at + 4] = Float.NEGATIVE_INFINITY;
        box[at + 5] = Float.NEGATIVE_INFINITY;
    }
}
