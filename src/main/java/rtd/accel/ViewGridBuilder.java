package rtd.accel;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;

/**
 * Builds a {@link ViewGrid}, in passes over arrays, each on all threads where it can be: every object's footprint on
 * the image and nearest distance ({@link ImageFootprint}); a place for it in the leaf, by the square of the image it
 * lies in, so that neighbours on the image lie side by side in memory; its numbers packed at that place
 * ({@link LeafObjects}); the cells' lists, with cells of the side {@link CellSide} chooses; and each list sorted
 * nearest first, so that a ray can stop at the first object beyond its hit ({@link NearestHit#testPlacesNearestFirst}).
 * The grid is the same for any number of threads. A builder builds one grid.
 */
final class ViewGridBuilder {

    /** An object that some ray of the picture can hit, one that none can, one without a box (a plane). */
    private static final byte SEEN = 0;
    private static final byte UNSEEN = 1;
    private static final byte UNBOUNDED = 2;
    /** The side of the squares by which the objects are ordered in the leaf, 2 to this power: the renderer's. */
    private static final int TILE_SHIFT = 3;
    /** A cell of more objects than this is sorted by {@link Arrays#sort}, not by insertion. */
    private static final int INSERTION_SORT_MOST = 32;

    private final List<IGeometry> objects;
    private final ForkJoinPool pool;
    private final int width;
    private final int height;

    /**
     * Per object in file order: its pixels x0, y0, x1, y1 (inclusive), or x0 > x1 if it is not {@link #SEEN}; let go
     * once the cells are filled.
     */
    private int[] footprints;
    /** For a {@link HitImage}'s tiles: per seen object in leaf order, its pixels as {@link #footprints} has them. */
    private int[] footprintsByPlace;
    /** Per object in file order: a distance from the ray's origin before which no ray hits it, if {@link #SEEN}. */
    private final float[] nearest;
    private final byte[] state;
    /** Per object in file order: its place in the leaf, −1 for one without a box. */
    private int[] leafOf;
    /** The places in the file of the objects without a box, in file order. */
    private int[] unboundedOrder;

    ViewGridBuilder(List<IGeometry> objects, int width, int height, ForkJoinPool pool) {
        this.objects = objects;
        this.pool = pool;
        this.width = width;
        this.height = height;
        this.footprints = new int[4 * objects.size()];
        this.nearest = new float[objects.size()];
        this.state = new byte[objects.size()];
    }

    /** The grid of the camera's rays through points up to {@code latestOffset} into pixels, {@code samples²} each. */
    ViewGrid build(ICamera camera, float latestOffset, int samples) {
        return build(ImageFootprint.of(camera, width, height, latestOffset), camera, latestOffset, samples);
    }

    /**
     * The grid of the objects' {@code footprint}s on a {@code width × height} image, for about {@code samples²} rays a
     * pixel; {@code camera} and {@code latestOffset} are what its rays are (a light's grid has no camera).
     */
    ViewGrid build(ImageFootprint footprint, ICamera camera, float latestOffset, int samples) {
        int shift = CellSide.choose(objects, footprint, width, height, samples);
        return build(footprint, camera, latestOffset, shift, true);
    }

    /**
     * As above, with cells of side {@code 1 << shift} (or larger, if they would hold too many entries), each cell's
     * objects nearest first if {@code sorted}, else in file order: a {@link HitImage}'s tiles, which test them all.
     */
    ViewGrid build(ImageFootprint footprint, ICamera camera, float latestOffset, int shift, boolean sorted) {
        Parts parts = new Parts(objects.size(), pool);
        int[][] perPart = new int[parts.parts][cellCount(shift)];
        measure(footprint, parts, shift, perPart);
        while (entries(perPart) > CellSide.MOST_ENTRIES && cellCount(shift) > 1) {
            // the sample missed objects that cover much of the image: larger cells, counted again
            shift++;
            perPart = new int[parts.parts][cellCount(shift)];
            count(parts, shift, perPart);
        }
        int columns = ViewGrid.cellsAlong(width, shift);
        int[] cellStart = new int[cellCount(shift) + 1];
        int[] fileOrder = leafOrder();
        LeafObjects packed = new LeafObjects(objects, fileOrder, new int[0], new float[0], pool, null);
        Bvh leaf = Bvh.oneLeaf(packed, unboundedOrder, objects);
        float[] nearestByPlace = new float[fileOrder.length];
        // the image's tiles read each object's pixels by its place: in leaf order, beside its numbers, not one cache
        // miss each in the file's order
        footprintsByPlace = sorted ? null : new int[4 * fileOrder.length];
        int[] places = fill(parts, perPart, shift, columns, cellStart, nearestByPlace);
        footprints = null; // the places' copy, or nothing, is all that is read from here on
        if (sorted) {
            sortNearestFirst(cellStart, places, nearestByPlace, pool);
        }
        return new ViewGrid(leaf, camera, width, height, latestOffset, shift, cellStart, places, nearestByPlace);
    }

    /**
     * After a {@link #build} of an image's tiles (not {@code sorted}), per object in leaf order: its pixels x0, y0, x1,
     * y1 (inclusive), if a ray sees it.
     */
    int[] footprintsByPlace() {
        return footprintsByPlace;
    }

    /**
     * Each object's box, footprint and nearest distance, and whether a ray can see it; and, part by part of
     * {@code parts}, how many objects each cell of side {@code 1 << shift} gets, into {@code perPart}.
     */
    private void measure(ImageFootprint footprint, Parts parts, int shift, int[][] perPart) {
        int columns = ViewGrid.cellsAlong(width, shift);
        parts.run((start, end, part) -> {
            float[] box = new float[6];
            for (int f = start; f < end; f++) {
                nearest[f] = footprint.putObject(objects.get(f), box, footprints, 4 * f);
                state[f] = nearest[f] == nearest[f] ? SEEN : ImageFootprint.isFinite(box) ? UNSEEN : UNBOUNDED;
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
     * Gives each object with a box its place in the leaf, {@link #leafOf}: the objects seen by the square of 8 × 8
     * pixels their footprint's middle lies in, square after square, row by row; then those no ray sees. Answers the
     * places' objects ({@code fileOrder}), and lists those without a box in {@link #unboundedOrder}.
     */
    private int[] leafOrder() {
        int across = ViewGrid.cellsAlong(width, TILE_SHIFT);
        int tiles = across * ViewGrid.cellsAlong(height, TILE_SHIFT);
        leafOf = new int[objects.size()];
        int[] next = new int[tiles + 2];
        int unbounded = 0;
        for (int f = 0; f < leafOf.length; f++) {
            int at = 4 * f;
            if (state[f] == UNBOUNDED) {
                leafOf[f] = -1;
                unbounded++;
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
        unboundedOrder = new int[unbounded];
        for (int f = 0, u = 0; f < leafOf.length; f++) {
            if (leafOf[f] >= 0) {
                int place = next[leafOf[f]]++;
                leafOf[f] = place;
                fileOrder[place] = f;
            } else {
                unboundedOrder[u++] = f;
            }
        }
        return fileOrder;
    }

    /**
     * Writes each seen object's leaf place into the cells its footprint overlaps, part by part of the objects in
     * parallel, from each part's counts per cell ({@link #measure}, in {@code perPart}, which become each part's next
     * place per cell): a cell's objects take places in the order of the parts, each part's from where the earlier
     * parts' end, and {@code cellStart} becomes the running sum; then each part writes its objects' places into theirs,
     * their nearest distance by place into {@code nearestByPlace}, and their pixels into {@link #footprintsByPlace} if
     * there is one. So a cell's objects come in file order, however many parts there are.
     */
    private int[] fill(Parts parts, int[][] perPart, int shift, int columns, int[] cellStart, float[] nearestByPlace) {
        int[] places = new int[Parts.runningSums(perPart, cellStart)];
        parts.run((start, end, part) -> {
            int[] cursor = perPart[part];
            for (int f = start; f < end; f++) {
                if (state[f] == SEEN) {
                    int at = 4 * f;
                    int place = leafOf[f];
                    nearestByPlace[place] = nearest[f];
                    if (footprintsByPlace != null) {
                        System.arraycopy(footprints, at, footprintsByPlace, 4 * place, 4);
                    }
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
     * Sorts each cell's objects by their nearest distance, in parallel by cells: by insertion, as a cell holds a dozen
     * or so, and a crowded cell (objects that cover the whole image, say) by their distances and places. A list that
     * runs from far to near is turned round first: a file that lists a mesh from the back to the front fills every cell
     * that way, the worst order for an insertion sort. Objects at the same distance may end in any order (file order,
     * its reverse, or by place): a ray's depth test breaks such ties by file order itself ({@link NearestHit}), so the
     * pictures do not depend on it.
     */
    private static void sortNearestFirst(int[] cellStart, int[] places, float[] nearestByPlace, ForkJoinPool pool) {
        new Parts(cellStart.length - 1, pool).run((first, end, part) -> {
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
