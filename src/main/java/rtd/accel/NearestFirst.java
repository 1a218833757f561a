package rtd.accel;

/**
 * The objects a {@link ViewGrid}'s cells list, nearest first: by a distance before which no hit
 * on each object lies, so that a ray can stop at the first object beyond its hit
 * ({@link NearestHit#testPlacesNearestFirst}). The builder writes the objects into their cells in
 * this order, so every cell's list comes out sorted, with no sort per cell.
 */
final class NearestFirst {

    /** The bits of a sort key taken at once: two passes over a float's 32. */
    private static final int DIGIT = 16;

    private NearestFirst() {
    }

    /**
     * The objects {@code f} with {@code seen[f]}, ordered by {@code nearest[f]} (negative
     * distances and −∞ too), and on a tie by {@code f}: a radix sort of the distances' bits, in
     * two stable passes of {@value #DIGIT} bits, which costs two passes over the objects however
     * they lie.
     */
    static int[] order(float[] nearest, boolean[] seen) {
        int count = 0;
        for (boolean s : seen) {
            count += s ? 1 : 0;
        }
        int[] objects = new int[count];
        for (int f = 0, k = 0; f < seen.length; f++) {
            if (seen[f]) {
                objects[k++] = f;
            }
        }
        int[] other = new int[count]; // the keys are looked up, not kept: a million objects' keys are 4 MB twice
        pass(objects, other, nearest, 0);
        pass(other, objects, nearest, DIGIT);
        return objects;
    }

    /**
     * The float's bits as an int whose unsigned order is the floats' order: a negative float's
     * bits order backwards, so they are turned round, and the sign bit flipped.
     */
    static int key(float distance) {
        int bits = Float.floatToIntBits(distance);
        return (bits ^ ((bits >> 31) & 0x7FFF_FFFF)) ^ 0x8000_0000;
    }

    /** One stable counting pass over {@code objects} into {@code into}, by the {@value #DIGIT} bits of their keys from bit {@code shift}. */
    private static void pass(int[] objects, int[] into, float[] nearest, int shift) {
        int[] next = new int[(1 << DIGIT) + 1];
        for (int f : objects) {
            next[((key(nearest[f]) >>> shift) & 0xFFFF) + 1]++;
        }
        for (int d = 1; d < next.length; d++) {
            next[d] += next[d - 1]; // now where each digit's objects start
        }
        for (int f : objects) {
            into[next[(key(nearest[f]) >>> shift) & 0xFFFF]++] = f;
        }
    }
}
