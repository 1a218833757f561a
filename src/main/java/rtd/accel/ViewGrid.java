package rtd.accel;

import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Rounding;
import rtd.scene.Scene;

/**
 * For the paper's orthographic camera, which objects each pixel's ray may hit: the image cut
 * into square cells of pixels, and for each cell the objects whose {@link ImageFootprint}
 * overlaps it, in file order. Not in the paper. When every ray runs in the same direction, the
 * search for what a ray hits is a search in two dimensions, on the image: a ray tests only the
 * objects of its cell, a few where the paper's loop tests all, and no tree is built or walked.
 *
 * <p>It serves only the camera's rays ({@link ViewGridTracer}), so it pays for scenes in flat
 * colours, where no other ray is traced; a scene with lights casts shadow rays in every
 * direction and needs the {@link Bvh}. The cells hold places in {@link #objects}, a hierarchy
 * of one leaf that holds every object in file order with its numbers packed for the test.
 *
 * <p>The cell's side is a power of two, chosen for the scene: small cells let a ray test fewer
 * objects, but an object then lies in more cells, which costs building and memory
 * ({@link #cellShift}).
 */
public final class ViewGrid {

    /** The most cell entries the grid is made with if a larger cell keeps under it (4 bytes each). */
    private static final long MOST_ENTRIES = 1L << 25;
    /** How many objects at most {@link #cellShift} looks at to estimate the entries. */
    private static final int SAMPLE = 1 << 16;

    /** The objects with a box, in file order, and those without. */
    final Bvh objects;
    final OrthographicCamera camera;
    final int width;
    final int height;
    /** The largest offset into its pixel of a ray that the grid serves: 0, the corner, unless samples. */
    final float latestOffset;
    /** The cell side is {@code 1 << shift} pixels. */
    final int shift;
    final int columns;
    final int rows;
    /** Cell c (row by row) holds {@code places[cellStart[c] .. cellStart[c + 1])}. */
    final int[] cellStart;
    /** The places in {@link #objects}' leaf of each cell's objects, cell after cell, each cell's in file order. */
    final int[] places;

    private ViewGrid(Bvh objects, OrthographicCamera camera, int width, int height, float latestOffset,
            int shift, int[] cellStart, int[] places) {
        this.objects = objects;
        this.camera = camera;
        this.width = width;
        this.height = height;
        this.latestOffset = latestOffset;
        this.shift = shift;
        this.columns = cellsAlong(width, shift);
        this.rows = cellsAlong(height, shift);
        this.cellStart = cellStart;
        this.places = places;
    }

    /**
     * The grid for {@code scene}, whose camera must be orthographic, for a {@code width × height}
     * picture with {@code samples × samples} rays per pixel, built with {@code threads} threads.
     */
    public static ViewGrid build(Scene scene, int width, int height, int samples, int threads) {
        OrthographicCamera camera = (OrthographicCamera) scene.camera();
        boolean parallel = threads > 1 && scene.objects().size() >= BvhBuilder.PARALLEL_THRESHOLD;
        ForkJoinPool pool = parallel ? new ForkJoinPool(threads) : null;
        try {
            Bvh objects = Bvh.oneLeaf(scene, pool);
            float latestOffset = samples == 1 ? 0 : (samples - 0.5f) / samples;
            Parts parts = new Parts(objects.leaves.fileOrder.length, pool);
            int[] footprints = footprints(objects, new ImageFootprint(camera, width, height, latestOffset), parts);
            int shift = cellShift(footprints, width, height, samples);
            int columns = cellsAlong(width, shift);
            int[] cellStart = new int[columns * cellsAlong(height, shift) + 1];
            int[] places = sort(footprints, shift, columns, cellStart, parts);
            return new ViewGrid(objects, camera, width, height, latestOffset, shift, cellStart, places);
        } finally {
            if (pool != null) {
                pool.shutdown();
            }
        }
    }

    /** Whether {@link #build} can make a grid for this scene: its camera's rays are parallel. */
    public static boolean fits(Scene scene) {
        return scene.camera() instanceof OrthographicCamera;
    }

    private static int cellsAlong(int pixels, int shift) {
        return ((pixels - 1) >> shift) + 1;
    }

    /**
     * Each object's pixels, four numbers a place in the leaf (x0, y0, x1, y1, inclusive), or
     * an empty range (x0 > x1) for an object no ray of the picture can hit.
     */
    private static int[] footprints(Bvh objects, ImageFootprint footprint, Parts parts) {
        LeafObjects leaves = objects.leaves;
        List<IGeometry> scene = objects.objects;
        int[] footprints = new int[4 * parts.count];
        parts.run((start, end) -> {
            for (int i = start; i < end; i++) {
                Rounding rounding = scene.get(leaves.fileOrder[i]).rounding();
                if (!footprint.put(leaves.boxes, 6 * i, rounding.linear(), rounding.quadratic(), footprints, 4 * i)) {
                    footprints[4 * i] = 1; // x0 > x1: none
                    footprints[4 * i + 2] = 0;
                }
            }
        });
        return footprints;
    }

    /**
     * The cell side's power of two for which building and tracing together cost least: each
     * entry of an object in a cell costs a write, and a test by each ray of the cell
     * ({@code 4^shift · samples²} rays). The entries are estimated on a sample of the objects.
     * A side whose grid would hold more than {@link #MOST_ENTRIES} entries is passed over when
     * a larger one does not.
     */
    private static int cellShift(int[] footprints, int width, int height, int samples) {
        int count = footprints.length / 4;
        int step = Math.max(1, count / SAMPLE);
        int best = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        for (int shift = 0; shift < 31; shift++) {
            long entries = 0;
            for (int i = 0; i < count; i += step) {
                entries += cellsOf(footprints, 4 * i, shift);
            }
            double estimate = (double) entries * count / ((count + step - 1) / step);
            double rays = (double) (1L << (2 * shift)) * samples * samples;
            double cost = estimate * (1 + rays) * (estimate > MOST_ENTRIES ? 1e6 : 1);
            if (cost < bestCost) {
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
     * Sorts the objects into their cells, part by part of the objects, in parallel: each part
     * counts its objects per cell; a cell's objects then take places in the order of the parts,
     * each part's from where the earlier parts' end, and {@code cellStart} becomes the running
     * sum; each part writes its objects' places into theirs. So each cell's objects are in file
     * order, however many parts there are.
     */
    private static int[] sort(int[] footprints, int shift, int columns, int[] cellStart, Parts parts) {
        int cells = cellStart.length - 1;
        int[][] next = new int[parts.parts][cells];
        parts.run((start, end, part) -> {
            int[] counts = next[part];
            for (int at = 4 * start; at < 4 * end; at += 4) {
                if (footprints[at] <= footprints[at + 2]) {
                    for (int y = footprints[at + 1] >> shift; y <= footprints[at + 3] >> shift; y++) {
                        for (int x = footprints[at] >> shift; x <= footprints[at + 2] >> shift; x++) {
                            counts[y * columns + x]++;
                        }
                    }
                }
            }
        });
        int total = 0;
        for (int c = 0; c < cells; c++) {
            cellStart[c] = total;
            for (int[] counts : next) {
                int count = counts[c];
                counts[c] = total;
                total += count;
            }
        }
        cellStart[cells] = total;
        int[] places = new int[total];
        parts.run((start, end, part) -> {
            int[] cursor = next[part];
            for (int i = start; i < end; i++) {
                int at = 4 * i;
                if (footprints[at] <= footprints[at + 2]) {
                    for (int y = footprints[at + 1] >> shift; y <= footprints[at + 3] >> shift; y++) {
                        for (int x = footprints[at] >> shift; x <= footprints[at + 2] >> shift; x++) {
                            places[cursor[y * columns + x]++] = i;
                        }
                    }
                }
            }
        });
        return places;
    }

    /** The cell of pixel (x, y). */
    int cellOf(int x, int y) {
        return (y >> shift) * columns + (x >> shift);
    }

    /** Whether no object lies in any cell of the pixels {@code [left, right) × [top, bottom)}. */
    boolean emptyOver(int left, int top, int right, int bottom) {
        for (int y = top >> shift; y <= (bottom - 1) >> shift; y++) {
            int first = y * columns + (left >> shift);
            int last = y * columns + ((right - 1) >> shift);
            if (cellStart[first] != cellStart[last + 1]) {
                return false;
            }
        }
        return true;
    }

    /** The number of cells. */
    public int cellCount() {
        return cellStart.length - 1;
    }

    /** The side of a cell in pixels. */
    public int cellSide() {
        return 1 << shift;
    }

    /** The number of objects in all cells together, an object counted once per cell it lies in. */
    public int entries() {
        return places.length;
    }

    /** A new tracer for this grid's camera rays; one per thread. */
    public ViewGridTracer newTracer() {
        return new ViewGridTracer(this);
    }
}
