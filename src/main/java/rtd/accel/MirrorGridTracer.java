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
 * Answers the rays that flat mirrors reflect from the camera's eye through {@link MirrorGrids}: such
 * a ray tests the objects of its cell, nearest first by their distance from the eye's image X, and
 * those without a box. Its cell holds every object it can hit; the depth test does not depend on the
 * order of the tests; and it stops only where the next object lies farther from X than its origin
 * does plus its nearest hit, so that no hit on that object or any after it can be nearer. So the
 * answer is the paper's loop's. Any ray whose line passes X as a mirrored one does is served the
 * same way, whatever made it; every other ray, and every shadow ray, goes to the tracer for the
 * others. Not thread-safe: one per thread.
 */
final class MirrorGridTracer implements Tracer {

    private final MirrorGrids.Grid[] grids;
    /** Per grid, the tests on its objects. */
    private final NearestHit[] hits;
    private final Tracer others;
    private long rays;

    MirrorGridTracer(List<MirrorGrids.Grid> grids, Tracer others) {
        this.grids = grids.toArray(MirrorGrids.Grid[]::new);
        this.hits = new NearestHit[this.grids.length];
        for (int g = 0; g < hits.length; g++) {
            hits[g] = new NearestHit(this.grids[g].cells().objects);
        }
        this.others = others;
    }

    @Override
    public Hit nearestHit(Ray ray) {
        for (int g = 0; g < grids.length; g++) {
            int cell = grids[g].cellOf(ray);
            if (cell >= 0) {
                rays++;
                ViewGrid cells = grids[g].cells();
                NearestHit hit = hits[g];
                Vector3f origin = ray.origin();
                Vector3f direction = ray.direction();
                hit.start(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
                hit.testUnbounded();
                hit.testPlacesNearestFirst(cells.places, cells.cellStart[cell], cells.cellStart[cell + 1],
                        cells.nearest, grids[g].originFromImage(ray));
                return hit.hit(ray);
            }
        }
        return others.nearestHit(ray);
    }

    @Override
    public boolean blocked(Ray ray, float distance) {
        return others.blocked(ray, distance);
    }

    @Override
    public void traceAll(RayBundle bundle, HitBuffer hits) {
        others.traceAll(bundle, hits);
    }

    @Override
    public boolean traceAtOnce(RayBundle bundle, HitBuffer hits) {
        return others.traceAtOnce(bundle, hits);
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
        WorkCount work = others.work().plus(new WorkCount(rays, Map.of(), 0).answeredBy("mirror grids"));
        for (NearestHit hit : hits) {
            work = work.plus(new WorkCount(0, hit.testsByKind(), 0));
        }
        return work;
    }
}
