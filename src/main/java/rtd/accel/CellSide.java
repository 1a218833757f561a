package rtd.accel;

import java.util.List;
import rtd.geometry.IGeometry;

/**
 * The side of a {@link ViewGrid}'s cells, a power of two of pixels: small cells let a ray test
 * fewer objects, but an object then lies in more cells, which costs building and memory. Chosen
 * from an estimate made on a sample of the objects.
 */
final class CellSide {

    /** The most cell entries the grid is made with if a larger cell keeps under it (4 bytes each). */
    static final long MOST_ENTRIES = 1L << 25;
    /** How many objects at most {@link #choose} measures to estimate the entries: enough for a mean. */
    static final int SAMPLE = 1 << 12;

    private CellSide() {
    }

    /**
     * The power of two of the side for which building and tracing together cost least: each
     * entry of an object in a cell costs a write, and a test by each ray of the cell
     * ({@code 4^shift · samples²} rays). The entries are estimated on a sample of the objects,
     * whose footprints are measured for it. A side whose grid would hold more than
     * {@link #MOST_ENTRIES} entries is passed over when a larger one does not;
     * {@link ViewGridBuilder} makes the cells larger still if the sample missed objects that cover
     * much of the image.
     */
    static int choose(List<IGeometry> objects, ImageFootprint footprint, int width, int height, int samples) {
        int[] sample = footprint.ofSample(objects, SAMPLE);
        int best = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        for (int shift = 0; shift < 31; shift++) {
            double estimate = estimate(sample, objects.size(), shift);
            double rays = (double) (1L << (2 * shift)) * samples * samples;
            double cost = estimate * (1 + rays) * (estimate > MOST_ENTRIES ? 1e6 : 1);
            if (cost <= bestCost) { // on a tie the larger cells: an empty grid is one cell
                best = shift;
                bestCost = cost;
            }
            if (1 << shift >= Math.max(width, height)) {
                break; // one cell holds the whole image: no more entries than objects
            }
        }
        return best;
    }

    /**
     * How many entries a grid of cells of side {@code 1 << shift} gets for {@code count} objects, estimated from the
     * footprints of a sample of them ({@link ImageFootprint#ofSample}); of side 1, how many tests their rays run.
     */
    static double estimate(int[] sample, int count, int shift) {
        long entries = 0;
        for (int at = 0; at < sample.length; at += 4) {
            entries += cellsOf(sample, at, shift);
        }
        return sample.length == 0 ? 0 : (double) entries * count / (sample.length / 4.0);
    }

    /** The number of cells of side {@code 1 << shift} that the footprint at {@code at} overlaps. */
    private static long cellsOf(int[] footprints, int at, int shift) {
        if (footprints[at] > footprints[at + 2]) {
            return 0;
        }
        long across = (footprints[at + 2] >> shift) - (footprints[at] >> shift) + 1;
        long down = (footprints[at + 3] >> shift) - (footprints[at + 1] >> shift) + 1;
        return across * down;
    }
}
