package rtd.accel;

import java.util.List;
import java.util.Map;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.render.WorkCount;

/**
 * Answers the shadow rays that {@link LightGrids} serve, the same as the paper's loop; every other
 * ray goes to the tracer for the others. Not thread-safe: one per thread.
 */
final class LightGridTracer implements Tracer {

    private final LightGrids.Grid[] grids;
    /** Per grid, the tests on its objects. */
    private final NearestHit[] hits;
    private final Tracer others;
    private long rays;

    LightGridTracer(List<LightGrids.Grid> grids, Tracer others) {
        this.grids = grids.toArray(LightGrids.Grid[]::new);
        this.hits = new NearestHit[this.grids.length];
        for (int g = 0; g < hits.length; g++) {
            hits[g] = new NearestHit(this.grids[g].cells().objects);
        }
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
                Vector3f origin = ray.origin();
                Vector3f direction = ray.direction();
                hit.start(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
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
    public void traceAll(RayBundle rays, HitBuffer hits) {
        others.traceAll(rays, hits);
    }

    @Override
    public boolean traceAtOnce(RayBundle rays, HitBuffer hits) {
        return others.traceAtOnce(rays, hits);
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
        for (int g = 0; g < grids.length; g++) {
            NearestHit hit = hits[g];
            work = work.plus(new WorkCount(0, hit.testsByKind(), 0));
        }
        return work;
    }
}
