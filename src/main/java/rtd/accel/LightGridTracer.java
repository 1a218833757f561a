package rtd.accel;

import java.util.List;
import java.util.Map;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.render.WorkCount;

/**
 * Answers the shadow rays that {@link LightGrids} serve, the same as the paper's loop: each grid's objects are tested
 * by a {@link NearestHit} of its own. Every other ray goes to the tracer for the others. Not thread-safe: one per
 * thread.
 */
final class LightGridTracer implements Tracer {

    private final LightGrids.Grid[] grids;
    /** Per grid, the tests on its objects. */
    private final NearestHit[] hits;
    private final Tracer others;
    /** The rays the grids answered. */
    private long rays;

    LightGridTracer(List<LightGrids.Grid> grids, Tracer others) {
        this.grids = grids.toArray(LightGrids.Grid[]::new);
        this.hits = grids.stream().map(grid -> new NearestHit(grid.cells().objects)).toArray(NearestHit[]::new);
        this.others = others;
    }

    @Override
    public boolean blocked(Ray ray, float distance) {
        for (int g = 0; g < grids.length; g++) {
            int cell = grids[g].cellOf(ray, distance);
            if (cell >= 0) {
                rays++;
                ViewGrid cells = grids[g].cells();
                NearestHit hit = hits[g];
                hit.start(ray);
                hit.limitTo(distance);
                hit.testUnbounded();
                hit.testPlacesUntilHit(cells.places, cells.cellStart[cell], cells.cellStart[cell + 1], cells.nearest,
                        grids[g].farthestHit(distance));
                return hit.best() >= 0;
            }
        }
        return others.blocked(ray, distance);
    }

    @Override
    public Hit nearestHit(Ray ray) {
        return others.nearestHit(ray);
    }

    @Override
    public void traceAll(RayBundle bundle, HitBuffer buffer) {
        others.traceAll(bundle, buffer);
    }

    @Override
    public boolean traceAtOnce(RayBundle bundle, HitBuffer buffer) {
        return others.traceAtOnce(bundle, buffer);
    }

    @Override
    public long testsRun() {
        long tests = others.testsRun();
        for (NearestHit hit : hits) {
            tests += hit.testsRun();
        }
        return tests;
    }

    @Override
    public WorkCount work() {
        WorkCount work = others.work().plus(new WorkCount(rays, Map.of(), 0).answeredBy("light grids"));
        for (NearestHit hit : hits) {
            work = work.plus(new WorkCount(0, hit.testsByKind(), 0));
        }
        return work;
    }
}
