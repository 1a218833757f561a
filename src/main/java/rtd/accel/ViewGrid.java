package rtd.accel;

import rtd.camera.ICamera;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * For a camera's rays, which objects each pixel's ray may hit: the image cut into square cells
 * of pixels, and for each cell the objects whose {@link ImageFootprint} overlaps it, nearest
 * first. Not in the paper. When every ray runs in the same direction (the paper's orthographic
 * camera) or leaves the same point (the perspective camera), each object shows on a patch of the
 * image, and the search for what a ray hits is a search in two dimensions: a ray tests only the
 * objects of its cell, a few where the paper's loop tests all, and no tree is built or walked.
 *
 * <p>It serves only the camera's rays ({@link ViewGridTracer}). The cells hold places in
 * {@link #objects}, a hierarchy of one leaf that holds every object with its numbers packed for
 * the test. A ray tests its cell's objects nearest first, and stops at the first that lies beyond
 * a hit it has found: where objects hide each other, it tests the few in front.
 *
 * <p>The cell's side is a power of two, chosen for the scene ({@link CellSide}).
 */
public final class ViewGrid {

    /** The objects with a box, in one leaf, and those without. */
    final Bvh objects;
    final ICamera camera;
    final int width;
    final int height;
    /** The largest offset into its pixel of a ray that the grid serves: 0, the corner, unless samples. */
    final float latestOffset;
    /** The cell side is {@code 1 << shift} pixels. */
    final int shift;
    final int columns;
    /** Cell c (row by row) holds {@code places[cellStart[c] .. cellStart[c + 1])}. */
    final int[] cellStart;
    /**
     * The places in {@link #objects}' leaf of each cell's objects, cell after cell, each cell's
     * nearest first: in the order of {@link #nearest}.
     */
    final int[] places;
    /**
     * Per place in the leaf, a distance from the ray's origin before which no camera ray hits the
     * object (in a light's grid, from the light, {@link LightGrids}): it never decreases along a cell's objects,
     * so a ray that has a hit nearer than an object's may stop there
     * ({@link NearestHit#testPlacesNearestFirst}; a shadow ray, where it is beyond its origin,
     * {@link NearestHit#testPlacesUntilHit}).
     */
    final float[] nearest;

    ViewGrid(Bvh objects, ICamera camera, int width, int height, float latestOffset,
            int shift, int[] cellStart, int[] places, float[] nearest) {
        this.objects = objects;
        this.camera = camera;
        this.width = width;
        this.height = height;
        this.latestOffset = latestOffset;
        this.shift = shift;
        this.columns = cellsAlong(width, shift);
        this.cellStart = cellStart;
        this.places = places;
        this.nearest = nearest;
    }

    /**
     * The grid for {@code scene}, whose camera must {@link #fits fit}, for a {@code width × height}
     * picture with {@code samples × samples} rays per pixel, built with {@code threads} threads.
     */
    public static ViewGrid build(Scene scene, int width, int height, int samples, int threads) {
        float latestOffset = samples == 1 ? 0 : (samples - 0.5f) / samples;
        return Parts.onPool(threads, scene.objects().size(), pool -> new ViewGridBuilder(scene.objects(), width, height,
                pool).build(scene.camera(), latestOffset, samples));
    }

    /** Whether {@link #build} can make a grid for this scene's camera: the orthographic or the perspective one. */
    public static boolean fits(Scene scene) {
        return ImageFootprint.fits(scene.camera());
    }

    /** How many cells of side {@code 1 << shift} cover {@code pixels}. */
    static int cellsAlong(int pixels, int shift) {
        return ((pixels - 1) >> shift) + 1;
    }

    /**
     * Whether the bundle holds rays of {@code camera}'s {@code width × height} picture, for pixels of the picture,
     * through points up to {@code latestOffset} into their pixels.
     */
    static boolean serves(RayBundle bundle, ICamera camera, int width, int height, float latestOffset) {
        RayBundle.Pixels p = bundle.pixels();
        return p != null && p.camera() == camera && p.width() == width && p.height() == height && p.left() >= 0
                && p.top() >= 0 && p.right() <= width && p.bottom() <= height
                && p.sampleX() >= 0 && p.sampleX() <= latestOffset && p.sampleY() >= 0 && p.sampleY() <= latestOffset;
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

    /** A new tracer for this grid's camera rays, and the paper's loop for any other ray; one per thread. */
    public ViewGridTracer newTracer() {
        return new ViewGridTracer(this, null);
    }

    /** A new tracer for this grid's camera rays, and {@code others} for any other ray; one per thread. */
    public ViewGridTracer newTracer(Tracer others) {
        return new ViewGridTracer(this, others);
    }
}
