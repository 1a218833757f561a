package rtd.accel;

import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;

/**
 * Builds a {@link ViewGrid}, in passes over arrays, each on all threads where it can be: every
 * object's footprint on the image and nearest distance ({@link ImageFootprint}); a place for it in the
 * leaf, by the square of the image it lies in, so that neighbours on the image lie side by side
 * in memory; its numbers packed at that place ({@link LeafObjects}); the cells' lists, with cells
 * of the side {@link CellSide} chooses, each list nearest first: the objects are written into
 * the cells in that order ({@link NearestFirst}).
 * The grid is the same for any number of threads.
 */
final class ViewGridBuilder {

    /** An object that some ray of the picture can hit, one that none can, one without a box (a plane). */
    private static final byte SEEN = 0;
    private static final byte UNSEEN = 1;
    private static final byte UNBOUNDED = 2;
    /** The side of the squares by which the objects are ordered in the leaf, 2 to this power: the renderer's squares. */
    private static final int TILE_SHIFT = 3;

    private final List<IGeometry> objects;
    private final ForkJoinPool pool;
    private final int width;
    private final int height;

    /**
     * Per object in file order: its pixels x0, y0, x1, y1 (inclusive), or x0 > x1 if it is not
     * {@link #SEEN}; let go once {@link #recordsIn} has them in the order of the cells' lists, for
     * the memory of a million objects.
     */
    private int[] footprints;
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
        return build(ImageFootprint.of(camera, width, height, latestOffset), camera, latestOffset, samples);
    }

    /**
     * The grid of the objects' {@code footprint}s on a {@code width × height} image, for about
     * {@code samples²} rays a pixel; {@code camera} and {@code latestOffset} are what its rays
     * are (a {@link LightGrid}'s has no camera).
     */
    ViewGrid build(ImageFootprint footprint, ICamera camera, float latestOffset, int samples) {
        int shift = CellSide.choose(objects, footprint, width, height, samples);
        measure(footprint, new Parts(objects.size(), pool));
        int[] fileOrder = leafOrder();
        float[] nearestByPlace = new float[fileOrder.length];
        int[] order = NearestFirst.order(nearest, seen());
        Parts parts = new Parts(order.length, pool);
        int[] records = recordsIn(order, parts, nearestByPlace);
        footprints = null;
        int[][] perPart = new int[parts.parts][cellCount(shift)];
        count(records, parts, shift, perPart);
        while (entries(perPart) > CellSide.MOST_ENTRIES && cellCount(shift) > 1) {
            // the sample missed objects that cover much of the image: larger cells, counted again
            shift++;
            perPart = new int[parts.parts][cellCount(shift)];
            count(records, parts, shift, perPart);
        }
        int columns = ViewGrid.cellsAlong(width, shift);
        int[] cellStart = new int[cellCount(shift) + 1];
        Bvh leaf = Bvh.oneLeaf(pack(fileOrder), unboundedOrder(), objects);
        int[] places = fill(records, parts, perPart, shift, columns, cellStart);
        return new ViewGrid(leaf, camera, width, height, latestOffset, shift, cellStart, places, nearestByPlace);
    }

    /** Each object's box, footprint and nearest distance, and whether a ray can see it. */
    private void measure(ImageFootprint footprint, Parts parts) {
        parts.run((start, end, part) -> {
            float[] box = new float[6];
            for (int f = start; f < end; f++) {
                nearest[f] = footprint.putObject(objects.get(f), box, footprints, 4 * f);
                state[f] = nearest[f] == nearest[f] ? SEEN : ImageFootprint.isFinite(box) ? UNSEEN : UNBOUNDED;
            }
        });
    }

    /** Per object in file order, whether a ray of the picture can see it. */
    private boolean[] seen() {
        boolean[] seen = new boolean[state.length];
        for (int f = 0; f < seen.length; f++) {
            seen[f] = state[f] == SEEN;
        }
        return seen;
    }

    /** The numbers of an object that {@link #recordsIn} keeps: its footprint's four and its leaf place. */
    private static final int RECORD = 5;

    /**
     * What the passes that follow read of the objects of {@code order}, in that order,
     * {@value #RECORD} numbers each: its footprint and its place in the leaf. So they read one
     * record after the other, not all over memory (a million random spheres lie, in the order of
     * their distances, nowhere near their order in the file). Writes each one's nearest distance
     * by place into {@code nearestByPlace} on the way.
     */
    private int[] recordsIn(int[] order, Parts parts, float[] nearestByPlace) {
        int[] records = new int[RECORD * order.length];
        parts.run((start, end, part) -> {
            for (int k = start; k < end; k++) {
                int f = order[k];
                int at = RECORD * k;
                System.arraycopy(footprints, 4 * f, records, at, 4);
                records[at + 4] = leafOf[f];
                nearestByPlace[leafOf[f]] = nearest[f]; // each place once: the parts write apart
            }
        });
        return records;
    }

    /**
     * How many objects each cell of side {@code 1 << shift} gets, part by part of the seen
     * objects, whose {@link #recordsIn} {@code records} holds in order, into {@code perPart}.
     */
    private void count(int[] records, Parts parts, int shift, int[][] perPart) {
        int columns = ViewGrid.cellsAlong(width, shift);
        parts.run((start, end, part) -> {
            int[] counts = perPart[part];
            for (int at = RECORD * start; at < RECORD * end; at += RECORD) {
                for (int y = records[at + 1] >> shift; y <= records[at + 3] >> shift; y++) {
                    for (int x = records[at] >> shift; x <= records[at + 2] >> shift; x++) {
                        counts[y * columns + x]++;
                    }
                }
            }
        });
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

    private int cellCount(int shift) {
        return CellSide.cellCount(width, height, shift);
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
     * Writes each seen object's leaf place into the cells its footprint overlaps, in parallel by
     * parts of the seen objects nearest first (their {@link #recordsIn} {@code records}), from each
     * part's counts per cell ({@link #count}, in {@code perPart}, which become each part's next
     * place per cell): a cell's objects take places in the order of the parts, each part's from
     * where the earlier parts' end, and {@code cellStart} becomes the running sum; then each part
     * writes its objects' places into theirs. So a cell's objects come nearest first, however many
     * parts there are.
     */
    private int[] fill(int[] records, Parts parts, int[][] perPart, int shift, int columns, int[] cellStart) {
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
            for (int at = RECORD * start; at < RECORD * end; at += RECORD) {
                int place = records[at + 4];
                for (int y = records[at + 1] >> shift; y <= records[at + 3] >> shift; y++) {
                    for (int x = records[at] >> shift; x <= records[at + 2] >> shift; x++) {
                        places[cursor[y * columns + x]++] = place;
                    }
                }
            }
        });
        return places;
    }
}
