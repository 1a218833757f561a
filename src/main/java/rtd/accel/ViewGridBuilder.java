package rtd.accel;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Rounding;

/**
 * Builds a {@link ViewGrid}, in passes over arrays, each on all threads where it can be: every
 * object's footprint on the image and nearest distance ({@link ImageFootprint}); a place for it in the
 * leaf, by the square of the image it lies in, so that neighbours on the image lie side by side
 * in memory; its numbers packed at that place ({@link LeafObjects}); the cells' lists; and each
 * list sorted nearest first. The grid is the same for any number of threads.
 */
final class ViewGridBuilder {

    /** An object that some ray of the picture can hit, one that none can, one without a box (a plane). */
    private static final byte SEEN = 0;
    private static final byte UNSEEN = 1;
    private static final byte UNBOUNDED = 2;
    /** The side of the squares by which the objects are ordered in the leaf, 2 to this power: the renderer's squares. */
    private static final int TILE_SHIFT = 3;

    /** The most cell entries the grid is made with if a larger cell keeps under it (4 bytes each). */
    private static final long MOST_ENTRIES = 1L << 25;
    /** How many objects at most {@link #cellShift} measures to estimate the entries: enough for a mean. */
    private static final int SAMPLE = 1 << 12;
    /** A cell of more objects than this is sorted by {@link Arrays#sort}, not by insertion. */
    private static final int INSERTION_SORT_MOST = 32;

    private final List<IGeometry> objects;
    private final ForkJoinPool pool;
    private final int width;
    private final int height;

    /** Per object in file order: its pixels x0, y0, x1, y1 (inclusive), or x0 > x1 if it is not {@link #SEEN}. */
    private final int[] footprints;
    /** Per object in file order: a distance from the ray's origin before which no ray hits it, if it is {@link #SEEN}. */
    private final float[] nearest;
    private final byte[] state;
    /** Per object in file order: its place in the leaf, −1 for one without a box. */
    private int[] leafOf;

    ViewGridBuilder(List<IGeometry> objects, int width, int height, ForkJoinPool pool) {
        this.objects = objects;
        this.pool = pool;
        this.width = width;
        this.height = height;
        this.footprints = new int[4 * objects.size()];
        this.nearest = new float[objects.size()];
        this.state = new byte[objects.size()];
    }

    /** The grid of {@code camera}'s rays through points up to {@code latestOffset} into their pixels, {@code samples²} a pixel. */
    ViewGrid build(ICamera camera, float latestOffset, int samples) {
        ImageFootprint footprint = ImageFootprint.of(camera, width, height, latestOffset);
        int shift = cellShift(footprint, samples);
        Parts parts = new Parts(objects.size(), pool);
        int[][] perPart = new int[parts.parts][cellCount(shift)];
        measure(footprint, parts, shift, perPart);
        while (entries(perPart) > MOST_ENTRIES && cellCount(shift) > 1) {
            // the sample missed objects that cover much of the image: larger cells, counted again
            shift++;
            perPart = new int[parts.parts][cellCount(shift)];
            count(parts, shift, perPart);
        }
        int columns = ViewGrid.cellsAlong(width, shift);
        int[] cellStart = new int[cellCount(shift) + 1];
        int[] fileOrder = leafOrder();
        Bvh leaf = Bvh.oneLeaf(pack(fileOrder), unboundedOrder(), objects);
        float[] nearestByPlace = new float[fileOrder.length];
        int[] places = fill(parts, perPart, shift, columns, cellStart, nearestByPlace);
        sortNearestFirst(cellStart, places, nearestByPlace);
        return new ViewGrid(leaf, camera, width, height, latestOffset, shift, cellStart, places, nearestByPlace);
    }

    /**
     * Each object's box, footprint and nearest distance, and whether a ray can see it; and, part by part
     * of {@code parts}, how many objects each cell of side {@code 1 << shift} gets, into
     * {@code perPart}.
     */
    private void measure(ImageFootprint footprint, Parts parts, int shift, int[][] perPart) {
        int columns = ViewGrid.cellsAlong(width, shift);
        parts.run((start, end, part) -> {
            float[] box = new float[6];
            for (int f = start; f < end; f++) {
                nearest[f] = footprintOf(objects.get(f), footprint, box, footprints, 4 * f);
                state[f] = nearest[f] == nearest[f] ? SEEN : isFinite(box) ? UNSEEN : UNBOUNDED;
                countCells(f, shift, columns, perPart[part]);
            }
        });
    }

    /** How many objects each cell of side {@code 1 << shift} gets, part by part, into {@code perPart}. */
    private void count(Parts parts, int shift, int[][] perPart) {
        int columns = ViewGrid.cellsAlong(width, shift);
        parts.run((start, end, part) -> {
            for (int f = start; f < end; f++) {
                countCells(f, shift, columns, perPart[part]);
            }
        });
    }

    /** Counts object {@code f} in the cells its footprint overlaps, if it is {@link #SEEN}. */
    private void countCells(int f, int shift, int columns, int[] counts) {
        if (state[f] != SEEN) {
            return;
        }
        int at = 4 * f;
        for (int y = footprints[at + 1] >> shift; y <= footprints[at + 3] >> shift; y++) {
            for (int x = footprints[at] >> shift; x <= footprints[at + 2] >> shift; x++) {
                counts[y * columns + x]++;
            }
        }
    }

    /** All the counts together: the entries the cells would hold. */
    private static long entries(int[][] perPart) {
        long sum = 0;
        for (int[] counts : perPart) {
            for (int count : counts) {
                sum += count;
            }
        }
        return sum;
    }

    /** How many cells of side {@code 1 << shift} cover the image. */
    private int cellCount(int shift) {
        return ViewGrid.cellsAlong(width, shift) * ViewGrid.cellsAlong(height, shift);
    }

    /**
     * {@code object}'s footprint into {@code into[at ..]} (x0 > x1 if no ray sees it), and its
     * nearest distance, NaN if no ray sees it (or it has no box); {@code box} is room for its
     * bounds, which it holds afterwards.
     */
    private static float footprintOf(IGeometry object, ImageFootprint footprint, float[] box, int[] into, int at) {
        object.putBounds(box, 0);
        Rounding rounding = object.rounding();
        float nearest = isFinite(box) ? footprint.put(box, 0, rounding.linear(), rounding.quadratic(), into, at)
                : Float.NaN;
        if (nearest != nearest) {
            into[at] = 1; // x0 > x1: no pixel
            into[at + 2] = 0;
        }
        return nearest;
    }

    private static boolean isFinite(float[] box) {
        for (float value : box) {
            if (!Float.isFinite(value)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Gives each object with a box its place in the leaf, {@link #leafOf}: the objects seen by
     * the square of 8 × 8 pixels their footprint's middle lies in, square after square, row by
     * row; then those no ray sees. Answers the places' objects ({@code fileOrder}).
     */
    private int[] leafOrder() {
        int across = ViewGrid.cellsAlong(width, TILE_SHIFT);
        int tiles = across * ViewGrid.cellsAlong(height, TILE_SHIFT);
        leafOf = new int[objects.size()];
        int[] next = new int[tiles + 2];
        for (int f = 0; f < leafOf.length; f++) {
            int at = 4 * f;
            if (state[f] == UNBOUNDED) {
                leafOf[f] = -1;
                continue;
            }
            int tile = state[f] == UNSEEN ? tiles
                    : ((footprints[at + 1] + footprints[at + 3]) / 2 >> TILE_SHIFT) * across
                            + ((footprints[at] + footprints[at + 2]) / 2 >> TILE_SHIFT);
            leafOf[f] = tile;
            next[tile + 1]++;
        }
        for (int t = 1; t < next.length; t++) {
            next[t] += next[t - 1]; // now where each square's objects start
        }
        int[] fileOrder = new int[next[tiles + 1]];
        for (int f = 0; f < leafOf.length; f++) {
            if (leafOf[f] >= 0) {
                int place = next[leafOf[f]]++;
                leafOf[f] = place;
                fileOrder[place] = f;
            }
        }
        return fileOrder;
    }

    /** The numbers of the objects' tests, packed in leaf order. */
    private LeafObjects pack(int[] fileOrder) {
        return new LeafObjects(objects, fileOrder, new float[0], ObjectArrays.of(0), Parts.loopOn(pool), null);
    }

    /** The places in the file of the objects without a box, in file order. */
    private int[] unboundedOrder() {
        int count = 0;
        for (byte s : state) {
            count += s == UNBOUNDED ? 1 : 0;
        }
        int[] order = new int[count];
        for (int f = 0, k = 0; k < count; f++) {
            if (state[f] == UNBOUNDED) {
                order[k++] = f;
            }
        }
        return order;
    }

    /**
     * The cell side's power of two for which building and tracing together cost least: each
     * entry of an object in a cell costs a write, and a test by each ray of the cell
     * ({@code 4^shift · samples²} rays). The entries are estimated on a sample of the objects, whose footprints are measured for it. A side whose grid
     * would hold more than {@link #MOST_ENTRIES} entries is passed over when a larger one does not;
     * {@link #build} makes the cells larger still if the sample missed objects that cover much
     * of the image.
     */
    private int cellShift(ImageFootprint footprint, int samples) {
        int count = objects.size();
        int step = Math.max(1, count / SAMPLE);
        int[] sample = new int[4 * ((count + step - 1) / step)];
        float[] box = new float[6];
        for (int f = 0, at = 0; f < count; f += step, at += 4) {
            footprintOf(objects.get(f), footprint, box, sample, at);
        }
        int best = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        for (int shift = 0; shift < 31; shift++) {
            long entries = 0;
            for (int at = 0; at < sample.length; at += 4) {
                entries += cellsOf(sample, at, shift);
            }
            double estimate = sample.length == 0 ? 0 : (double) entries * count / (sample.length / 4.0);
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

    /** The number of cells of side {@code 1 << shift} that the footprint at {@code at} overlaps. */
    private static long cellsOf(int[] footprints, int at, int shift) {
        if (footprints[at] > footprints[at + 2]) {
            return 0;
        }
        long across = (footprints[at + 2] >> shift) - (footprints[at] >> shift) + 1;
        long down = (footprints[at + 3] >> shift) - (footprints[at + 1] >> shift) + 1;
        return across * down;
    }

    /**
     * Writes each seen object's leaf place into the cells its footprint overlaps, part by part of
     * the objects in parallel, from each part's counts per cell ({@link #measure}, in
     * {@code perPart}, which become each part's next place per cell): a cell's objects take places in the order of the parts, each part's from
     * where the earlier parts' end, and {@code cellStart} becomes the running sum; then each
     * part writes its objects' places into theirs, and their nearest distance by place into
     * {@code nearestByPlace}. So a cell's objects come in file order, however many parts there are.
     */
    private int[] fill(Parts parts, int[][] perPart, int shift, int columns, int[] cellStart, float[] nearestByPlace) {
        int cells = cellStart.length - 1;
        int total = 0;
        for (int c = 0; c < cells; c++) {
            cellStart[c] = total;
            for (int[] counts : perPart) {
                int count = counts[c];
                counts[c] = total;
                total += count;
            }
        }
        cellStart[cells] = total;
        int[] places = new int[total];
        parts.run((start, end, part) -> {
            int[] cursor = perPart[part];
            for (int f = start; f < end; f++) {
                if (state[f] == SEEN) {
                    int at = 4 * f;
                    int place = leafOf[f];
                    nearestByPlace[place] = nearest[f];
                    for (int y = footprints[at + 1] >> shift; y <= footprints[at + 3] >> shift; y++) {
                        for (int x = footprints[at] >> shift; x <= footprints[at + 2] >> shift; x++) {
                            places[cursor[y * columns + x]++] = place;
                        }
                    }
                }
            }
        });
        return places;
    }

    /**
     * Sorts each cell's objects by their nearest distance, in parallel by cells: by insertion, as
     * a cell holds a dozen or so, and a crowded cell (objects that cover the whole image, say) by
     * their distances and places. A list that runs from far to near is turned round first: a
     * file that lists a mesh from the back to the front fills every cell that way, the worst
     * order for an insertion sort.
     */
    private void sortNearestFirst(int[] cellStart, int[] places, float[] nearestByPlace) {
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
                for (int k = from + 1; k < to; k++) {
                    int place = places[k];
                    float distance = nearestByPlace[place];
                    int j = k - 1;
                    while (j >= from && nearestByPlace[places[j]] > distance) {
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
