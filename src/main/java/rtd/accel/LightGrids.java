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

    private final List<LightGrid> grids;

    private LightGrids(List<LightGrid> grids) {
        this.grids = grids;
    }

    /**
     * The grids of {@code scene}'s lights, for a {@code width × height} picture with
     * {@code samples²} rays a pixel (about as many shadow rays go to each light), built with
     * {@code threads} threads. A light among the objects gets none: its shadow rays go to the
     * tracer for the others.
     */
    public static LightGrids build(Scene scene, int width, int height, int samples, int threads) {
        List<IGeometry> objects = scene.objects();
        float[] box = boxOf(objects);
        int size = (int) Math.max(16, Math.min(4096, Math.sqrt((double) width * height) * samples));
        boolean parallel = threads > 1 && objects.size() >= BvhBuilder.PARALLEL_THRESHOLD;
        ForkJoinPool pool = parallel ? new ForkJoinPool(threads) : null;
        try {
            List<LightGrid> grids = new ArrayList<>();
            for (Light light : scene.lights()) {
                LightGrid grid = box == null ? null : LightGrid.build(objects, box, light.position(), size, pool);
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
    private static float[] boxOf(List<IGeometry> objects) {
        float[] all = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        float[] box = new float[6];
        boolean any = false;
        for (IGeometry object : objects) {
            object.putBounds(box, 0);
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
