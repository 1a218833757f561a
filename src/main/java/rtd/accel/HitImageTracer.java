package rtd.accel;

import java.util.Map;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.render.HitBuffer;
import rtd.render.LinearTracer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.render.WorkCount;

/**
 * Answers the camera's rays from a {@link HitImage}: each ray's hit was found before the render, so a ray reads it,
 * and the tests its pixel took, from its pixel. Any other ray (a ray given alone, a ray through another point of its
 * pixel, of another camera or picture) runs the tests on every object, as the paper's loop does: right for any ray,
 * and fast only for the image's.
 *
 * <p>Not thread-safe: it keeps counters of its own. Use one per thread.
 */
public final class HitImageTracer implements Tracer {

    private final HitImage image;
    /** Per kind of the objects with a box, the tests of the rays answered from the image. */
    private final long[] tests;
    private long rays;
    /** The paper's loop for the rays that are not the image's, made when first needed. */
    private Tracer others;

    HitImageTracer(HitImage image) {
        this.image = image;
        this.tests = new long[image.kindNames.length];
    }

    @Override
    public Hit nearestHit(Ray ray) {
        return others().nearestHit(ray);
    }

    private Tracer others() {
        if (others == null) {
            others = new LinearTracer(image.scene);
        }
        return others;
    }

    /** The camera's rays read their pixels; other rays go one by one to the loop. */
    @Override
    public void traceAll(RayBundle bundle, HitBuffer hits) {
        if (!image.serves(bundle)) {
            others().traceAll(bundle, hits);
            return;
        }
        RayBundle.Pixels p = bundle.pixels();
        int across = p.right() - p.left();
        for (int y = p.top(), i = 0; y < p.bottom(); y++, i += across) {
            int pixel = y * image.width + p.left();
            hits.set(i, across, pixel, image.index, image.t, image.distance, image.rayTests);
            countTests(pixel, across);
        }
        rays += bundle.count();
    }

    /** Counts by kind the tests of pixels {@code [pixel, pixel + across)} of the image. */
    private void countTests(int pixel, int across) {
        if (image.tests == null) { // one kind: a pixel's tests less those of the objects without a box
            for (int at = pixel; at < pixel + across; at++) {
                tests[0] += image.rayTests[at] - image.unbounded.length;
            }
            return;
        }
        int kinds = tests.length;
        for (int k = 0; k < kinds; k++) {
            for (int at = pixel * kinds + k, end = (pixel + across) * kinds; at < end; at += kinds) {
                tests[k] += image.tests[at];
            }
        }
    }

    /** The camera's rays of a run of squares, each read from its pixel, all at once. */
    @Override
    public boolean traceAtOnce(RayBundle bundle, HitBuffer hits) {
        if (!image.serves(bundle)) {
            return false;
        }
        traceAll(bundle, hits);
        return true;
    }

    @Override
    public long testsRun() {
        long all = rays * image.unbounded.length;
        for (long ofKind : tests) {
            all += ofKind;
        }
        return all + (others != null ? others.testsRun() : 0);
    }

    @Override
    public WorkCount work() {
        Map<String, Long> byKind = TestCounts.byName(image.kindNames, tests, image.unbounded, rays);
        WorkCount own = new WorkCount(rays, byKind, 0).answeredBy("image of hits");
        return others != null ? own.plus(others.work()) : own;
    }
}
