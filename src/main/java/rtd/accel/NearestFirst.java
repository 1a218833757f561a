package rtd.accel;

import java.util.Arrays;
import java.util.concurrent.ForkJoinPool;

/**
 * Sorts a {@link ViewGrid}'s cell lists nearest first, by a distance before which no hit on each
 * object lies, so that a ray can stop at the first object beyond its hit
 * ({@link NearestHit#testPlacesNearestFirst}).
 */
final class NearestFirst {

    /** A cell of more objects than this is sorted by {@link Arrays#sort}, not by insertion. */
    private static final int INSERTION_SORT_MOST = 32;

    private NearestFirst() {
    }

    /**
     * Sorts each cell's objects by their nearest distance, in parallel by cells: by insertion, as
     * a cell holds a dozen or so, and a crowded cell (objects that cover the whole image, say) by
     * their distances and places. A list that runs from far to near is turned round first: a
     * file that lists a mesh from the back to the front fills every cell that way, the worst
     * order for an insertion sort. Objects at the same distance may end in any order (file order,
     * its reverse, or by place): a ray's depth test breaks such ties by file order itself
     * ({@link NearestHit}), so the pictures do not depend on it.
     */
    static void sort(int[] cellStart, int[] places, float[] nearestByPlace, ForkJoinPool pool) {
        new Parts(cellStart.length - 1, pool).run((first, end) -> {
            for (int c = first; c < end; c++) {
                int from = cellStart[c];
                int to = cellStart[c + 1];
                if (to - from > INSERTION_SORT_MOST) {
                    sortCrowded(places, from, to, nearestByPlace);
                    continue;
                }
                if (to - from > 1 && nearestByPlace[places[from]] > nearestByPlace[places[to - 1]]) {
                    reverse(places, from, to);
                }
                // j > beforeFrom, not j >= from: the JIT compiles the first form once, and gave up on the second
                int beforeFrom = from - 1;
                for (int k = from + 1; k < to; k++) {
                    int place = places[k];
                    float distance = nearestByPlace[place];
                    int j = k - 1;
                    while (j > beforeFrom && nearestByPlace[places[j]] > distance) {
                        places[j + 1] = places[j];
                        j--;
                    }
                    places[j + 1] = place;
                }
            }
        });
    }

    private static void reverse(int[] places, int from, int to) {
        for (int i = from, j = to - 1; i < j; i++, j--) {
            int swap = places[i];
            places[i] = places[j];
            places[j] = swap;
        }
    }

    /**
     * Sorts {@code places[from .. to)} by distance, then place: each as one long, the distance's
     * bits turned into an int that orders as the floats do (negative ones too), above the place.
     */
    static void sortCrowded(int[] places, int from, int to, float[] nearestByPlace) {
        long[] keys = new long[to - from];
        for (int k = from; k < to; k++) {
            int bits = Float.floatToIntBits(nearestByPlace[places[k]]);
            bits ^= (bits >> 31) & 0x7FFF_FFFF; // a negative float's bits order backwards: turn them round
            keys[k - from] = (long) bits << 32 | places[k];
        }
        Arrays.sort(keys);
        for (int k = from; k < to; k++) {
            places[k] = (int) keys[k - from];
        }
    }
}
