package rtd.accel;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.function.BiFunction;
import rtd.geometry.IGeometry;

/**
 * What the lights' and the mirrors' grids share: each grid is a {@link ViewGrid} seen from one point
 * ({@link PointFootprint}), whose "pixels" are the directions from that point on a square picture, and the grids
 * together hold copies of at most {@link #MOST_PACKED} objects. Not in the paper or Part II.
 */
public abstract class PointGrids<G extends PointGrids.Grid> {

    /**
     * How many objects all the grids may hold copies of together: each packs every object's numbers for the test,
     * which for a million triangles is most of the memory. The points after that many (the first in the file get
     * grids, and the first always) leave their rays to the tree.
     */
    static final long MOST_PACKED = 2_000_000;
    /** The side of a picture at least and at most, in pixels: 4,096² cells are as many as memory bears. */
    private static final int SMALLEST = 16;
    private static final int LARGEST = 4096;

    /** One point's grid: the cells of its picture. */
    interface Grid {
        ViewGrid cells();
    }

    private final List<G> grids;

    PointGrids(List<G> grids) {
        this.grids = grids;
    }

    /** The grids, one for each point that has one. */
    List<G> grids() {
        return grids;
    }

    /** How many points have a grid. */
    public int count() {
        return grids.size();
    }

    /** The objects in all the grids' cells together. */
    public long entries() {
        long entries = 0;
        for (G grid : grids) {
            entries += grid.cells().entries();
        }
        return entries;
    }

    /** The side of a picture of about {@code wanted} pixels, within its least and its most. */
    static int side(double wanted) {
        return (int) Math.max(SMALLEST, Math.min(LARGEST, wanted));
    }

    /**
     * The grids that {@code grid} makes (null for none) of {@code sources}, in their order, on a pool of
     * {@code threads} threads for a scene of {@code objects} objects, as long as they copy no more than
     * {@code mostPacked} objects together, and one always.
     */
    static <S, G> List<G> build(List<S> sources, int objects, int threads, long mostPacked,
            BiFunction<S, ForkJoinPool, G> grid) {
        long most = Math.max(1, mostPacked / Math.max(1, objects));
        return Parts.onPool(threads, objects, pool -> {
            List<G> built = new ArrayList<>();
            for (S source : sources) {
                if (built.size() >= most) {
                    break;
                }
                G made = grid.apply(source, pool);
                if (made != null) {
                    built.add(made);
                }
            }
            return List.copyOf(built);
        });
    }

    /** The cells of {@code objects} seen through {@code footprint}, on a picture of {@code size × size} pixels. */
    static ViewGrid cells(List<IGeometry> objects, PointFootprint footprint, int size, ForkJoinPool pool) {
        // no camera: the grid's "pixels" are directions from the point; a ray shows anywhere in its pixel (1)
        return new ViewGridBuilder(objects, size, size, pool).build(footprint, null, 1, 1);
    }

    /** The box of all objects that have a finite one, or null if none has. */
    static float[] boxOf(List<IGeometry> objects) {
        float[] all = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        float[] box = new float[6];
        boolean any = false;
        for (IGeometry object : objects) {
            KnownShapes.putBox(object, box, 0);
            if (ImageFootprint.isFinite(box)) {
                any = true;
                for (int k = 0; k < 3; k++) {
                    all[k] = Math.min(all[k], box[k]);
                    all[k + 3] = Math.max(all[k + 3], box[k + 3]);
                }
            }
        }
        return any ? all : null;
    }
}
