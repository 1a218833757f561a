package rtd.accel;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import rtd.geometry.IGeometry;
import rtd.render.RayBundle;
import rtd.scene.Scene;

/**
 * The nearest hit of every pixel's camera ray through its corner (Listing 4.1), found before the render object by
 * object. Not in the paper, whose loops go pixel by pixel and test every object (Listing 4.2 around Listing 4.3):
 * here they go the other way round, objects outside and pixels inside, as a graphics card's depth buffer draws, and
 * each object runs its own test only on the pixels of its {@link ImageFootprint}, where alone its rays can hit it.
 * Each pixel keeps the winner of the paper's depth test, which does not depend on the order of the tests; so every
 * pixel gets the loop's hit, to the last bit.
 *
 * <p>The image is cut into tiles of {@value #TILE} × {@value #TILE} pixels, each listing the objects whose footprint
 * overlaps it (a {@link ViewGrid} of that cell side, unsorted), and each tile is drawn by one thread alone
 * ({@link TileOfHits}), so the image is the same for any number of threads. Against the view grid, whose rays test
 * their cell's objects nearest first and stop early, it tests more (every object on every pixel of its footprint,
 * hidden or not) but builds far less: a few hundred tiles' lists, unsorted. It serves flat pictures of many objects
 * at one ray a pixel ({@link HitImageTracer}).
 */
public final class HitImage {

    /** The side of a tile is 2 to this power: its rays and best hits fit in a core's nearest caches. */
    static final int SHIFT = 6;
    static final int TILE = 1 << SHIFT;
    /**
     * The most tests a pixel on average: where objects lie deeper behind each other, the view grid's rays, which test
     * the front objects only, take less time.
     */
    static final long MOST_TESTS_A_PIXEL = 32;
    /** The most pixels, a little over 3840 × 2160: the image takes 16 bytes a pixel or more, more than the picture. */
    static final long MOST_PIXELS = 1L << 23;

    final Scene scene;
    final int width;
    final int height;
    final int columns;
    /** Per pixel, row by row: the place in the file of the object its ray hits, −1 for none; its t and |P − O|. */
    final int[] index;
    final float[] t;
    final float[] distance;
    /** The names of the kinds of the objects with a box ({@link LeafObjects#kindNames}). */
    final String[] kindNames;
    /**
     * Per pixel, per kind ({@code tests[pixel · kinds + kind]}): the tests its ray ran on objects with a box; null
     * where they are all of one kind, whose tests are a pixel's {@link #rayTests} less those without a box.
     */
    final int[] tests;
    /** Per pixel: all the tests its ray ran, the objects without a box' too. */
    final int[] rayTests;
    /** The objects without a box (planes), which every pixel's ray tests. */
    final IGeometry[] unbounded;
    private final int entries;

    private HitImage(Scene scene, int width, int height, ViewGrid tiles) {
        this.scene = scene;
        this.width = width;
        this.height = height;
        this.columns = ViewGrid.cellsAlong(width, SHIFT);
        this.index = new int[width * height];
        this.t = new float[width * height];
        this.distance = new float[width * height];
        this.kindNames = tiles.objects.leaves.kindNames;
        this.tests = kindNames.length == 1 ? null : new int[width * height * kindNames.length];
        this.rayTests = new int[width * height];
        this.unbounded = tiles.objects.unbounded;
        this.entries = tiles.entries();
    }

    /**
     * Whether the image is worth building for {@code scene}'s camera and a {@code width × height} picture: a camera
     * {@link ImageFootprint} fits, no more than {@link #MOST_PIXELS}, and no more than {@link #MOST_TESTS_A_PIXEL}
     * tests a pixel by the footprints of a sample of the objects.
     */
    public static boolean pays(Scene scene, int width, int height) {
        if (!ImageFootprint.fits(scene.camera()) || (long) width * height > MOST_PIXELS) {
            return false;
        }
        List<IGeometry> objects = scene.objects();
        int[] sample = ImageFootprint.of(scene.camera(), width, height, 0).ofSample(objects, CellSide.SAMPLE);
        return CellSide.estimate(sample, objects.size(), 0) <= MOST_TESTS_A_PIXEL * width * height;
    }

    /** The image of {@code scene}'s hits for a {@code width × height} picture, built with {@code threads} threads. */
    public static HitImage build(Scene scene, int width, int height, int threads) {
        List<IGeometry> objects = scene.objects();
        return Parts.onPool(threads, objects.size(), pool -> {
            ViewGridBuilder builder = new ViewGridBuilder(objects, width, height, pool);
            ViewGrid tiles = builder.build(ImageFootprint.of(scene.camera(), width, height, 0), scene.camera(), 0,
                    SHIFT, false);
            HitImage image = new HitImage(scene, width, height, tiles);
            int count = image.tileCount();
            int[] footprints = builder.footprintsByPlace();
            AtomicInteger next = new AtomicInteger();
            new Parts(count, pool).run((start, end, part) -> { // each thread takes the next tile not yet taken
                TileOfHits tile = new TileOfHits(image, tiles, footprints);
                for (int k = next.getAndIncrement(); k < count; k = next.getAndIncrement()) {
                    tile.draw((k % image.columns) << SHIFT, (k / image.columns) << SHIFT);
                }
            });
            return image;
        });
    }

    /** Whether the bundle holds rays of this image's camera and picture, through the corners of its pixels. */
    boolean serves(RayBundle bundle) {
        return ViewGrid.serves(bundle, scene.camera(), width, height, 0);
    }

    /** The object entries of all tiles together, an object counted once per tile its footprint overlaps. */
    public int entries() {
        return entries;
    }

    /** The number of tiles. */
    public int tileCount() {
        return columns * ViewGrid.cellsAlong(height, SHIFT);
    }

    /** The side of a tile in pixels. */
    public int tileSide() {
        return TILE;
    }

    /** A new tracer for the camera's rays, and the paper's loop for any other ray; one per thread. */
    public HitImageTracer newTracer() {
        return new HitImageTracer(this);
    }
}
