package rtd.cli;

import java.util.Locale;
import java.util.function.Supplier;
import rtd.accel.Bvh;
import rtd.accel.ViewGrid;
import rtd.render.LinearTracer;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * What a run finds its hits with, as {@code --accel} chose it and built it: the tracers (one per
 * thread) and the line {@code --stats} gives the build.
 *
 * @param tracers   a new tracer for each thread
 * @param built     what was built, for {@code --stats}: made only if asked, as formatting numbers
 *                  the first time costs a run of the paper's example some 20 ms
 * @param walksTree whether the tracers walk a tree, so that nodes per ray mean something
 */
record Accelerator(Supplier<Tracer> tracers, Supplier<String> built, boolean walksTree) {

    /**
     * The fewest objects for which {@code --accel auto} takes the view grid: below, the hierarchy's
     * squares of rays, tuned on the paper's two spheres, are as fast, and already compiled for
     * the warm-up.
     */
    static final int GRID_THRESHOLD = 1_000;

    /**
     * Builds what {@code accel} asks for {@code scene}, for a {@code width × height} picture with
     * {@code samples²} rays per pixel, with {@code threads} threads.
     */
    static Accelerator of(Scene scene, Accel accel, int width, int height, int samples, int threads) {
        int objects = scene.objects().size();
        boolean gridFits = ViewGrid.fits(scene); // both cameras: false only for a camera added later
        boolean grid = accel == Accel.grid && gridFits
                || accel == Accel.auto && gridFits && scene.lights().isEmpty() && objects >= GRID_THRESHOLD;
        if (grid) {
            ViewGrid viewGrid = ViewGrid.build(scene, width, height, samples, threads);
            return new Accelerator(viewGrid::newTracer, () -> String.format(Locale.ROOT,
                    "view grid of %s of %d × %d pixels, %s", StatsReport.count(viewGrid.cellCount(), "cell"),
                    viewGrid.cellSide(), viewGrid.cellSide(), StatsReport.count(viewGrid.entries(), "entry", "entries")), false);
        }
        if (accel != Accel.none && objects > 0) {
            Bvh bvh = Bvh.build(scene, threads);
            return new Accelerator(bvh::newTracer, () -> "BVH of " + StatsReport.count(bvh.nodeCount(), "node"), true);
        }
        return new Accelerator(() -> new LinearTracer(scene), () -> "no BVH: the paper's loop tests every object", false);
    }
}
