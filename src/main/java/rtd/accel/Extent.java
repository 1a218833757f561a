package rtd.accel;

/**
 * What the {@link BvhBuilder} must know of a group of objects to split it: the box around
 * their boxes, and the box around their centres (along which axis they spread, and where the
 * bins lie). Both grow as objects are added; boxes are {min x, y, z, max x, y, z}.
 */
final class Extent {

    private final float[] box = new float[6];
    private final float[] centres = new float[6];

    private Extent() {
        clear();
    }

    /** An extent of no objects. */
    static Extent empty() {
        return new Extent();
    }

    /** Forgets every object added. */
    void clear() {
        setEmpty(box);
        setEmpty(centres);
    }

    /** Adds the object whose box is {@code boxes[boxAt .. +5]} and centre {@code centrePoints[centreAt .. +2]}. */
    void add(float[] boxes, int boxAt, float[] centrePoints, int centreAt) {
        for (int k = 0; k < 3; k++) {
            box[k] = FastMath.min(box[k], boxes[boxAt + k]);
            box[k + 3] = FastMath.max(box[k + 3], boxes[boxAt + k + 3]);
            centres[k] = FastMath.min(centres[k], centrePoints[centreAt + k]);
            centres[k + 3] = FastMath.max(centres[k + 3], centrePoints[centreAt + k]);
        }
    }

    /** Adds every object of {@code other}. */
    void add(Extent other) {
        grow(box, other.box);
        grow(centres, other.centres);
    }

    /** Grows the box {@code box} to hold the box {@code other}. */
    static void grow(float[] box, float[] other) {
        for (int k = 0; k < 3; k++) {
            box[k] = FastMath.min(box[k], other[k]);
            box[k + 3] = FastMath.max(box[k + 3], other[k + 3]);
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
        box[0] = Float.POSITIVE_INFINITY;
        box[1] = Float.POSITIVE_INFINITY;
        box[2] = Float.POSITIVE_INFINITY;
        box[3] = Float.NEGATIVE_INFINITY;
        box[4] = Float.NEGATIVE_INFINITY;
        box[5] = Float.NEGATIVE_INFINITY;
    }
}
