package rtd.accel;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.Tracer;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * For shadow rays, a grid seen from each light that lies outside the box of the scene's objects:
 * the shadow rays' counterpart of the camera's {@link ViewGrid}. The objects seen from the light
 * ({@link PointFootprint}) are sorted into the cells of a square picture of the directions from
 * it; a shadow ray towards the light tests the objects of its cell and those without a box, and
 * stops at the first hit before the light ({@link LightGridTracer}): its cell holds every object
 * it can hit, so the answer is the paper's loop's. A ray that no grid serves (one that does not
 * end at a light, runs too far, or comes from outside the picture) goes to the tracer for the
 * others. Not in the paper or Part II.
 */
public final class LightGrids {

    /**
     * How many objects all the grids may hold copies of together: each packs every object's numbers for the test,
     * which for a million triangles is most of the memory. The lights after that many (the first in the file get
     * grids, and the first always) leave their rays to the tree.
     */
    static final long MOST_PACKED = 2_000_000;
    /** The side of a picture at least and at most, in pixels: 4,096² cells are as many as memory bears. */
    private static final int SMALLEST = 16;
    private static final int LARGEST = 4096;

    /**
     * One light's grid: the footprints seen from it and the cells of its picture ({@code cells.width}
     * pixels square), and how far short of the light the shader's shadow rays end
     * ({@link Light#clearance}): a ray is served as if it ran on to the light, where the grid's
     * geometry is exact, and its hits are still only those nearer than its own end.
     */
    record Grid(PointFootprint footprint, ViewGrid cells, float clearance) {

        /**
         * The grid of {@code objects} seen from {@code light}, whose objects with a box lie in
         * {@code box}, on a picture of {@code size × size} pixels; null if the light lies too near or
         * among them ({@link PointFootprint#around}).
         */
        static Grid build(List<IGeometry> objects, float[] box, Light light, int size, ForkJoinPool pool) {
            PointFootprint footprint = PointFootprint.around(light.position(), box, size);
            if (footprint == null) {
                return null;
            }
            // no camera: the grid's "pixels" are directions from the light; a ray shows anywhere in its pixel (1)
            ViewGrid cells = new ViewGridBuilder(objects, size, size, pool).build(footprint, null, 1, 1);
            return new Grid(footprint, cells, light.clearance());
        }

        /**
         * How far from the light a hit of a served ray of length {@code distance} can lie, at most:
         * {@code distance + c + g}, as its origin lies at most that far (c the clearance) and its hits
         * lie between the origin and the end, within the gap g of the light ({@link PointFootprint});
         * a second g and a millionth are room for rounding past the end.
         */
        float farthestHit(float distance) {
            return (float) (((double) distance + clearance + 2 * footprint.gap()) * (1 + 1e-6));
        }

        /**
         * The cell of a shadow ray, whose question is whether it hits anything nearer than
         * {@code distance}, or −1 if the grid does not serve it: served if, run on by the clearance,
         * it ends at the light.
         */
        int cellOf(Ray ray, float distance) {
            Vector3f origin = ray.origin();
            Vector3f direction = ray.direction();
            double length = Math.sqrt((double) direction.x() * direction.x() + (double) direction.y() * direction.y()
                    + (double) direction.z() * direction.z());
            double toLight = (double) distance + clearance;
            double along = toLight / length;
            int pixel = footprint.pixelOf(origin.x(), origin.y(), origin.z(), origin.x() + along * direction.x(),
                    origin.y() + along * direction.y(), origin.z() + along * direction.z(), toLight);
            return pixel < 0 ? -1 : cells.cellOf(pixel % cells.width, pixel / cells.width);
        }
    }

    /** No grid: every shadow ray goes to the tracer for the others. */
    public static final LightGrids NONE = new LightGrids(List.of());

    private final List<Grid> grids;

    private LightGrids(List<Grid> grids) {
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
        if (box == null) {
            return NONE;
        }
        int size = (int) Math.max(SMALLEST, Math.min(LARGEST, Math.sqrt((double) width * height) * samples));
        long most = Math.max(1, mostPacked / Math.max(1, objects.size()));
        return Parts.onPool(threads, objects.size(), pool -> {
            List<Grid> built = new ArrayList<>();
            for (Light light : scene.lights()) {
                if (built.size() >= most) {
                    break;
                }
                Grid grid = Grid.build(objects, box, light, size, pool);
                if (grid != null) {
                    built.add(grid);
                }
            }
            return new LightGrids(List.copyOf(built));
        });
    }

    /** The grids, one for each light that has one. */
    List<Grid> grids() {
        return grids;
    }

    /** How many lights have a grid. */
    public int count() {
        return grids.size();
    }

    /** The objects in all the grids' cells together. */
    public long entries() {
        long entries = 0;
        for (Grid grid : grids) {
            entries += grid.cells().entries();
        }
        return entries;
    }

    /** The box of all objects that have a finite one, or null if none has. */
    private static float[] boxOf(List<IGeometry> objects) {
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

    /** A new tracer for the shadow rays these grids serve, and {@code others} for every other ray; one per thread. */
    public Tracer newTracer(Tracer others) {
        return grids.isEmpty() ? others : new LightGridTracer(grids, others);
    }
}
