package rtd.accel;

import java.util.concurrent.ForkJoinPool;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * The nearest hit of every pixel's camera ray, found before the render, object by object. Not in
 * the paper, which goes pixel by pixel and tests every object (Listing 4.2 around Listing 4.3):
 * here the loops are the other way round, objects outside and pixels inside, as a graphics card's
 * z-buffer draws, and each object is tested only on the pixels of its footprint
 * ({@link ImageFootprint}), where alone its rays can hit it. Each pixel keeps the winner of the
 * paper's depth test, which does not depend on the order of the tests; so every pixel gets the
 * hit the paper's loop finds, to the last bit, with the same intersection tests.
 *
 * <p>It serves one ray a pixel, through the pixel's corner (Listing 4.1), of a camera that
 * shows every object on a patch of the image (both cameras). Built by {@link HitImageBuilder},
 * read by {@link HitImageTracer}. Against the {@link ViewGrid}, which lists for each cell of a
 * few pixels its objects nearest first and lets each ray stop early, it tests more (an object is
 * tested on every pixel of its footprint, hidden or not) but builds far less: a million spheres
 * take 16 million tests and 1.1 million entries in tiles of 64 × 64 pixels, against 5.5 million
 * tests and 6.2 million entries sorted in cells of 2 × 2 (docs/performance.md, the tenth round).
 */
public final class HitImage {

    final Scene scene;
    final ICamera camera;
    final int width;
    final int height;
    /** The objects without a box (planes), tested on every pixel; their places in the file. */
    final IGeometry[] unbounded;
    final int[] unboundedOrder;
    /** Per pixel, row by row: the place in the scene of the object its ray hits first, −1 for none. */
    final int[] index;
    /** Per pixel: the t of that hit, NaN for none. */
    final float[] t;
    /** Per pixel: the distance {@code |P − O|} of that hit, infinite for none. */
    final float[] distance;
    /** The names of the kinds of the objects with a box. */
    final String[] kindNames;
    /** Per kind, per pixel: the tests its ray ran on objects of that kind with a box. */
    final int[][] testsOfKind;
    private final int entries;
    private final int tiles;

    HitImage(Scene scene, int[] unboundedOrder, int width, int height, String[] kindNames, int entries, int tiles) {
        this.scene = scene;
        this.camera = scene.camera();
        this.width = width;
        this.height = height;
        this.unboundedOrder = unboundedOrder;
        this.unbounded = new IGeometry[unboundedOrder.length];
        for (int i = 0; i < unboundedOrder.length; i++) {
            unbounded[i] = scene.objects().get(unboundedOrder[i]);
        }
        this.index = new int[width * height];
        this.t = new float[width * height];
        this.distance = new float[width * height];
        this.kindNames = kindNames;
        this.testsOfKind = new int[kindNames.length][width * height];
        this.entries = entries;
        this.tiles = tiles;
    }

    /** Whether {@link #build} serves this scene's rays for pictures of {@code samples²} rays a pixel: one ray a pixel, either camera. */
    public static boolean fits(Scene scene, int samples) {
        return samples == 1 && ImageFootprint.fits(scene.camera());
    }

    /**
     * The image of {@code scene}'s nearest hits for a {@code width × height} picture, built with
     * {@code threads} threads; null if the objects' footprints together cover the image more
     * than {@link HitImageBuilder#MOST_TESTS_A_PIXEL} times over (objects deep behind each other,
     * each of which would be tested on all its pixels), or so often that the tiles' lists would
     * pass {@link HitImageBuilder#MOST_INTS} numbers, or if the picture has more than
     * {@link HitImageBuilder#MOST_PIXELS} pixels: the {@link ViewGrid}, whose rays test the
     * front objects only and whose cells grow with the entries, serves such a scene.
     */
    public static HitImage build(Scene scene, int width, int height, int threads) {
        return build(scene, width, height, threads, true);
    }

    /** As {@link #build(Scene, int, int, int)}, without the limits if {@code limited} is false (for tests). */
    static HitImage build(Scene scene, int width, int height, int threads, boolean limited) {
        ForkJoinPool pool = threads > 1 ? new ForkJoinPool(threads) : null; // the tiles' tests pay at any count
        try {
            return new HitImageBuilder(scene.objects(), scene.camera(), width, height, pool).build(scene, limited);
        } finally {
            if (pool != null) {
                pool.shutdown();
            }
        }
    }

    /** The object entries of all tiles together, an object counted once per tile its footprint overlaps. */
    public int entries() {
        return entries;
    }

    /** The number of tiles. */
    public int tileCount() {
        return tiles;
    }

    /** The side of a tile in pixels. */
    public int tileSide() {
        return HitImageBuilder.TILE;
    }

    /** A new tracer for the camera's rays, and the paper's loop for any other ray; one per thread. */
    public HitImageTracer newTracer() {
        return new HitImageTracer(this, null);
    }

    /** A new tracer for the camera's rays, and {@code others} for any other ray; one per thread. */
    public HitImageTracer newTracer(Tracer others) {
        return new HitImageTracer(this, others);
    }
}
