package rtd.accel;

import java.util.Collections;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.scene.Scene;

/**
 * Builds a {@link HitImage}, in three passes, each on all threads where it can be: every
 * object's footprint on the image ({@link ImageFootprint}) and kind; each tile of
 * {@value #TILE} × {@value #TILE} pixels' list of the objects whose footprint overlaps it, with
 * the part of the footprint inside the tile and a copy of the numbers of the object's test (as
 * {@link LeafObjects} packs them), so that a tile's tests read one stretch of memory (not for a
 * triangle: see {@link #copied}); and then,
 * tile by tile, the tests ({@link TileOfHits}). The image is the same for any number of threads:
 * each pixel's hit is decided in its own tile, by the depth test alone.
 */
final class HitImageBuilder {

    /** The side of a tile is 2 to this power: its rays and best hits fit in a core's nearest caches. */
    static final int SHIFT = 6;
    static final int TILE = 1 << SHIFT;
    /**
     * The most ints and floats the tiles' lists may take, 256 MiB: as much as the view grid's
     * lists at their most ({@link CellSide#MOST_ENTRIES} places and distances). A million spheres
     * take 12 million, the terrain of a million triangles 7.3 million (36 million while its
     * triangles' numbers were copied too: see {@link #copied}).
     */
    static final long MOST_INTS = 2 * CellSide.MOST_ENTRIES;
    /**
     * The most tests a pixel on average: each object is tested on every pixel of its footprint,
     * hidden or not, so where objects lie deeper behind each other (a million random spheres: 7.7
     * a pixel, the terrain 3.2) the view grid, whose rays test the front objects only, serves.
     * Measured (docs/performance.md, the fourteenth round): at 17 to 22 tests a pixel the image
     * still took a tenth to a third less time than the grid, for spheres and for triangles, at 44
     * to 45 less too, and at 120 (large spheres) a third more; 32 keeps inside where it pays.
     */
    static final long MOST_TESTS_A_PIXEL = 32;
    /**
     * The most pixels, a little over 3840 × 2160: the image takes 12 bytes a pixel and 4 more for
     * each kind of object, more than the picture itself; a larger picture takes the view grid.
     */
    static final long MOST_PIXELS = 1L << 23;

    private final List<IGeometry> objects;
    private final ICamera camera;
    private final int width;
    private final int height;
    private final ForkJoinPool pool;
    private final int columns;
    private final int tiles;
    /** Per object in file order: its pixels x0, y0, x1, y1 (inclusive); x0 > x1 if no ray sees it or it has no box. */
    private final int[] footprints;
    /** Per object in file order: its kind's number, {@link ObjectKinds#NONE} if it has no box (a plane). */
    private final ObjectKinds kinds;
    /** Per object in file order: how it is tested ({@link PackedTests}). */
    private final byte[] tests;

    HitImageBuilder(List<IGeometry> objects, ICamera camera, int width, int height, ForkJoinPool pool) {
        this.objects = objects;
        this.camera = camera;
        this.width = width;
        this.height = height;
        this.pool = pool;
        this.columns = ViewGrid.cellsAlong(width, SHIFT);
        this.tiles = columns * ViewGrid.cellsAlong(height, SHIFT);
        this.footprints = new int[4 * objects.size()];
        this.kinds = new ObjectKinds(objects.size());
        this.tests = new byte[objects.size()];
    }

    /** The image of {@code scene}'s hits; null if {@code limited} and it would pass the limits. */
    HitImage build(Scene scene, boolean limited) {
        if (limited && (long) width * height > MOST_PIXELS) {
            return null;
        }
        Parts parts = new Parts(objects.size(), pool);
        measure(ImageFootprint.of(camera, width, height, 0), parts);
        kinds.numberInFileOrder();
        int[][] entriesPerPart = new int[parts.parts][tiles];
        int[][] numbersPerPart = new int[parts.parts][tiles];
        long[] testsPerPart = new long[parts.parts];
        count(parts, entriesPerPart, numbersPerPart, testsPerPart);
        long tests = 0;
        for (long ofPart : testsPerPart) {
            tests += ofPart;
        }
        if (limited && tests > MOST_TESTS_A_PIXEL * width * height
                || limited && sum(entriesPerPart) * TileOfHits.ENTRY + sum(numbersPerPart) > MOST_INTS) {
            return null; // objects that hide each other deeply: the view grid tests the front ones only
        }
        int[] tileStart = new int[tiles + 1];
        int entryCount = Parts.runningSums(entriesPerPart, tileStart);
        int numberCount = Parts.runningSums(numbersPerPart, new int[tiles + 1]);
        int[] entries = new int[TileOfHits.ENTRY * entryCount];
        float[] numbers = new float[numberCount];
        fill(parts, entriesPerPart, numbersPerPart, entries, numbers);
        HitImage image = new HitImage(scene, unbounded(), width, height, kinds.names(),
                entryCount, tiles);
        drawTiles(image, tileStart, entries, numbers);
        return image;
    }

    /**
     * Each object's footprint, and its kind. A sample spread over the whole file goes first
     * (its footprints are not kept): the JIT compiles {@code put} for the branches its first
     * few thousand calls took, and meets a branch it never saw there (objects out of view, which
     * a file may hold only further on) by dropping the compiled code and starting again. With
     * the sample first, it compiles for the whole file once (the terrain of a million triangles:
     * this pass 0.27 → 0.20 s, medians of 7 alternating runs, and the slowest 0.91 → 0.22 s).
     */
    private void measure(ImageFootprint footprint, Parts parts) {
        footprint.ofSample(objects, CellSide.SAMPLE);
        parts.run((start, end) -> {
            float[] box = new float[6];
            String lastName = null;
            byte lastKind = -1;
            for (int f = start; f < end; f++) {
                IGeometry object = objects.get(f);
                footprint.putObject(object, box, footprints, 4 * f);
                if (!ImageFootprint.isFinite(box)) {
                    kinds.set(f, ObjectKinds.NONE);
                    continue;
                }
                String name = object.kind();
                if (!name.equals(lastName)) {
                    lastName = name;
                    lastKind = kinds.numberOf(name);
                }
                kinds.set(f, lastKind);
                tests[f] = PackedTests.of(object);
            }
        });
    }

    private boolean listed(int f) {
        return kinds.of(f) != ObjectKinds.NONE && footprints[4 * f] <= footprints[4 * f + 2];
    }

    /** The objects without a box, which every ray meets, in file order. */
    private int[] unbounded() {
        return IntStream.range(0, objects.size()).filter(f -> kinds.of(f) == ObjectKinds.NONE).toArray();
    }

    /**
     * Part by part of the objects, how many entries and how many numbers of tests each tile
     * gets, and how many tests the objects will run (the pixels of their footprints).
     */
    private void count(Parts parts, int[][] entriesPerPart, int[][] numbersPerPart, long[] testsPerPart) {
        parts.run((start, end, part) -> {
            int[] entries = entriesPerPart[part];
            int[] numbers = numbersPerPart[part];
            for (int f = start; f < end; f++) {
                if (listed(f)) {
                    int size = copied(tests[f]);
                    int at = 4 * f;
                    testsPerPart[part] += (long) (footprints[at + 2] - footprints[at] + 1)
                            * (footprints[at + 3] - footprints[at + 1] + 1);
                    for (int y = footprints[at + 1] >> SHIFT; y <= footprints[at + 3] >> SHIFT; y++) {
                        for (int x = footprints[at] >> SHIFT; x <= footprints[at + 2] >> SHIFT; x++) {
                            entries[y * columns + x]++;
                            numbers[y * columns + x] += size;
                        }
                    }
                }
            }
        });
    }

    /**
     * How many numbers of the test {@code test} an entry copies: none for a triangle, which
     * {@link TileOfHits} tests on its own numbers. A mesh keeps its triangles' numbers side by
     * side in a few hundred arrays already, in file order, as a tile lists them; a copy of them
     * (27 floats a triangle) took the terrain of a million triangles 112 MB and the time to
     * write them.
     */
    private static int copied(byte test) {
        return test == PackedTests.TRIANGLE ? 0 : PackedTests.size(test);
    }

    /** All the counts together. */
    private static long sum(int[][] perPart) {
        long sum = 0;
        for (int[] counts : perPart) {
            for (int count : counts) {
                sum += count;
            }
        }
        return sum;
    }

    /**
     * Writes each listed object into the tiles its footprint overlaps, part by part of the
     * objects in parallel: an entry of {@link TileOfHits#ENTRY} ints (its place in the file, its
     * pixels in the tile x0, y0, x1, y1, where its numbers start, its kind and test) and the
     * numbers of its test, if {@link #copied} copies them (a triangle's entry has no numbers,
     * and where they would start means nothing). A tile's objects come in file order, however
     * many parts there are.
     */
    private void fill(Parts parts, int[][] entriesPerPart, int[][] numbersPerPart, int[] entries, float[] numbers) {
        parts.run((start, end, part) -> {
            int[] entryCursor = entriesPerPart[part];
            int[] numberCursor = numbersPerPart[part];
            for (int f = start; f < end; f++) {
                if (!listed(f)) {
                    continue;
                }
                byte test = tests[f];
                int size = copied(test);
                int at = 4 * f;
                for (int y = footprints[at + 1] >> SHIFT; y <= footprints[at + 3] >> SHIFT; y++) {
                    for (int x = footprints[at] >> SHIFT; x <= footprints[at + 2] >> SHIFT; x++) {
                        int tile = y * columns + x;
                        int e = TileOfHits.ENTRY * entryCursor[tile]++;
                        int n = numberCursor[tile];
                        numberCursor[tile] += size;
                        entries[e] = f;
                        entries[e + 1] = Math.max(footprints[at], x << SHIFT);
                        entries[e + 2] = Math.max(footprints[at + 1], y << SHIFT);
                        entries[e + 3] = Math.min(footprints[at + 2], (x << SHIFT) + TILE - 1);
                        entries[e + 4] = Math.min(footprints[at + 3], (y << SHIFT) + TILE - 1);
                        entries[e + 5] = n;
                        entries[e + 6] = kinds.of(f) << PackedTests.BITS | test;
                        if (size > 0) {
                            PackedTests.put(objects.get(f), numbers, n);
                        }
                    }
                }
            }
        });
    }

    /** Runs the tests of every tile, each thread taking the next tile not yet taken. */
    private void drawTiles(HitImage image, int[] tileStart, int[] entries, float[] numbers) {
        AtomicInteger next = new AtomicInteger();
        Callable<Void> worker = () -> {
            TileOfHits tile = new TileOfHits(image, camera, entries, numbers);
            for (int k = next.getAndIncrement(); k < tiles; k = next.getAndIncrement()) {
                int left = (k % columns) << SHIFT;
                int top = (k / columns) << SHIFT;
                tile.draw(left, top, Math.min(width, left + TILE), Math.min(height, top + TILE), tileStart[k],
                        tileStart[k + 1]);
            }
            return null;
        };
        if (pool == null) {
            call(worker);
            return;
        }
        for (Future<Void> done : pool.invokeAll(Collections.nCopies(pool.getParallelism(), worker))) {
            Parts.join(done);
        }
    }

    private static void call(Callable<Void> worker) {
        try {
            worker.call();
        } catch (RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }
}
