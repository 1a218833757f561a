package rtd.accel;

/**
 * The smaller and larger of two floats by one plain comparison. {@link Math#min(float, float)}
 * also orders −0 before +0 and passes NaN on, which costs branches in the hot loops of the
 * hierarchy and is not needed there: a NaN only arises for a ray that runs exactly along a
 * box's face, and every box is wider than what it holds.
 */
final class FastMath {

    private FastMath() {
    }

    static float min(float a, float b) {
        return a < b ? a : b;
    }

    static float max(float a, float b) {
        return a > b ? a : b;
    }
}
