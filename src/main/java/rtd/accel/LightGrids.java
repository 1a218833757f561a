package rtd.accel;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.geometry.IGeometry;
import rtd.render.Tracer;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * A {@link LightGrid} for each light of a scene that lies outside the box of its objects: the
 * shadow rays' counterpart of the camera's {@link ViewGrid}. Not in the paper or Part II; it
 * answers the shadow rays' question faster, and the same as the paper's loop.
 */
public final class LightGrids {

    /**
     * How many objects all the grids may hold copies of together: each packs every object's
     * numbers for the test, which for a million triangles is most of the memory. The lights after that
     * many (the first in the file get grids, and the first light always) leave their shadow rays
     * to the tree.
     */
    static final long MOST_PACKED = 2_000_000;
    /** The side of a light's picture at least and at most, in pixels: 4,096² cells are as many as memory bears. */
    private static final int SMALLEST = 16;
    private static final int LARGEST = 4096;

    private final List<LightGrid> grids;

    private LightGrids(List<LightGrid> grids) {
        this.grids = grids;
    }

    /**
     * The grids of {@code scene}'s lights, for a {@code width × height} picture with
     * {@code samples²} rays a pixel (about as many shadow rays go to each light), built with
     * {@code threads} threads. The picture's side is about the image's, √(width · height) ·
     * samples. A light among the objects or beside them gets none ({@link PointFootprint#around}),
     * nor do the lights beyond {@link #MOST_PACKED} objects: their shadow rays go to the tracer for
     * the others.
     */
    public static LightGrids build(Scene scene, int width, int height, int samples, int threads) {
        return build(scene, width, height, samples, threads, MOST_PACKED);
    }

    /** As {@link #build(Scene, int, int, int, int)}, with grids for lights up to {@code mostPacked} objects. */
    static LightGrids build(Scene scene, int width, int height, int samples, int threads, long mostPacked) {
        List<IGeometry> objects = scene.objects();
        float[] box = boxOf(objects);
        int size = (int) Math.max(SMALLEST, Math.min(LARGEST, Math.sqrt((double) width * height) * samples));
        long most = Math.max(1, mostPacked / Math.max(1, objects.size()));
        boolean parallel = threads > 1 && objects.size() >= Parts.PARALLEL_THRESHOLD;
        ForkJoinPool pool = parallel ? new ForkJoinPool(threads) : null;
        try {
            List<LightGrid> grids = new ArrayList<>();
            for (Light light : scene.lights()) {
                if (box == null || grids.size() >= most) {
                    break;
                }
                LightGrid grid = LightGrid.build(objects, box, light, size, pool);
                if (grid != null) {
                    grids.add(grid);
                }
            }
            return new LightGrids(List.copyOf(grids));
        } finally {
            if (pool != null) {
                pool.shutdown();
            }
        }
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

    /** The grids, one for each light that has one. */
    List<LightGrid> grids() {
        return grids;
    }

    /** How many lights have a grid. */
    public int count() {
        return grids.size();
    }

    /** The objects in all the grids' cells together. */
    public long entries() {
        long entries = 0;
        for (LightGrid grid : grids) {
            entries += grid.cells.entries();
        }
        return entries;
    }

    /** A new tracer for the shadow rays these grids serve, and {@code others} for every other ray; one per thread. */
    public Tracer newTracer(Tracer others) {
        return grids.isEmpty() ? others : new LightGridTracer(grids, others);
    }
}
