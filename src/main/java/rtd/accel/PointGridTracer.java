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
 * A tracer in front of another that answers some rays from grids seen from one point (a light, or the eye's mirror
 * image): each grid's objects are tested by a {@link NearestHit} of its own, and every ray the grids do not serve
 * goes to the tracer for the others. Its subclasses say which rays a grid serves. Not thread-safe: one per thread.
 */
abstract class PointGridTracer implements Tracer {

    /** Per grid, the tests on its objects. */
    final NearestHit[] hits;
    final Tracer others;
    /** The rays the grids answered. */
    long rays;
    private final String answeredBy;

    PointGridTracer(List<ViewGrid> cells, Tracer others, String answeredBy) {
        this.hits = cells.stream().map(grid -> new NearestHit(grid.objects)).toArray(NearestHit[]::new);
        this.others = others;
        this.answeredBy = answeredBy;
    }

    @Override
    public Hit nearestHit(Ray ray) {
        return others.nearestHit(ray);
    }

    @Override
    public boolean blocked(Ray ray, float distance) {
        return others.blocked(ray, distance);
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
        WorkCount work = others.work().plus(new WorkCount(rays, Map.of(), 0).answeredBy(answeredBy));
        for (NearestHit hit : hits) {
            work = work.plus(new WorkCount(0, hit.testsByKind(), 0));
        }
        return work;
    }
}
