package rtd.accel;

import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.render.WorkCount;

/**
 * Finds what the camera's rays hit through a {@link ViewGrid}: each ray runs the paper's
 * intersection test and depth test (Listing 4.3, {@link NearestHit}) on the objects of its
 * pixel's cell, and on the objects without a box. The objects a ray can hit all lie in its cell,
 * and the depth test does not depend on the order of the tests, so the hit is the paper's loop's.
 * The cell lists its objects by a distance before which none of their hits lies, nearest first:
 * once that distance passes the hit found, by more than rounding can explain (as a box's entry
 * does in {@link BvhTracer}), no object after it can win or tie, and the ray stops.
 *
 * <p>A ray that is not the grid camera's goes to the tracer for the others (in a scene with lights,
 * the {@link LightGrids}' and then a {@link BvhTracer}); without one it runs the tests on every
 * object, as the paper's loop does: right for any ray, and fast only for the camera's.
 *
 * <p>Not thread-safe: it keeps the ray's state and counters of its own. Use one per thread.
 */
public final class ViewGridTracer implements Tracer {

    private final ViewGrid grid;
    private final Bvh objects;
    private final NearestHit hit;
    /** The tracer of the rays that are not the camera's, or null for the loop over every object. */
    private final Tracer others;
    private long rays;

    ViewGridTracer(ViewGrid grid, Tracer others) {
        this.grid = grid;
        this.objects = grid.objects;
        this.hit = new NearestHit(objects);
        this.others = others;
    }

    /** The tracer for the others' rays, else the loop over every object, for any ray. */
    @Override
    public Hit nearestHit(Ray ray) {
        if (others != null) {
            return others.nearestHit(ray);
        }
        rays++;
        hit.start(ray);
        hit.testUnbounded();
        if (objects.hasTree()) {
            hit.testLeaf(0);
        }
        return hit.hit(ray);
    }

    /** A shadow ray's question, for the tracer for the others' rays, else from the loop's hit. */
    @Override
    public boolean blocked(Ray ray, float distance) {
        return others != null ? others.blocked(ray, distance) : Tracer.super.blocked(ray, distance);
    }

    /** The camera's rays test their cells' objects; other rays go to the tracer for them, or one by one to the loop. */
    @Override
    public void traceAll(RayBundle bundle, HitBuffer hits) {
        if (!serves(bundle)) {
            if (others != null) {
                others.traceAll(bundle, hits);
            } else {
                Tracer.super.traceAll(bundle, hits);
            }
            return;
        }
        bundle.make();
        RayBundle.Pixels pixels = bundle.pixels();
        int squareWidth = pixels.right() - pixels.left();
        int[] cellStart = grid.cellStart;
        for (int i = 0; i < bundle.count(); i++) {
            int cell = grid.cellOf(pixels.left() + i % squareWidth, pixels.top() + i / squareWidth);
            rays++;
            long before = hit.testsRun();
            hit.start(bundle.originX(i), bundle.originY(i), bundle.originZ(i),
                    bundle.directionX(i), bundle.directionY(i), bundle.directionZ(i));
            hit.testUnbounded();
            hit.testPlacesNearestFirst(grid.places, cellStart[cell], cellStart[cell + 1], grid.nearest);
            hits.set(i, hit.best(), hit.bestT(), hit.bestDistance());
            hits.setTests(i, hit.testsRun() - before);
        }
    }

    /** The camera's rays of empty cells hit nothing, if every object has a box. */
    @Override
    public boolean traceAtOnce(RayBundle bundle, HitBuffer hits) {
        if (!serves(bundle)) {
            return others != null && others.traceAtOnce(bundle, hits);
        }
        RayBundle.Pixels p = bundle.pixels();
        if (objects.unbounded.length > 0 || !grid.emptyOver(p.left(), p.top(), p.right(), p.bottom())) {
            return false;
        }
        rays += bundle.count();
        hits.setMisses(bundle.count());
        return true;
    }

    private boolean serves(RayBundle bundle) {
        return ViewGrid.serves(bundle, grid.camera, grid.width, grid.height, grid.latestOffset);
    }

    @Override
    public long testsRun() {
        return hit.testsRun() + (others != null ? others.testsRun() : 0);
    }

    @Override
    public WorkCount work() {
        WorkCount own = new WorkCount(rays, hit.testsByKind(), 0)
                .answeredBy("view grid");
        return others != null ? own.plus(others.work()) : own;
    }
}
