package rtd.cli;

import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.function.Supplier;
import rtd.accel.Bvh;
import rtd.accel.LightGrids;
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
 *                  the first time is slow
 * @param walksTree whether the tracers walk a tree, so that nodes per ray mean something
 */
record Accelerator(Supplier<Tracer> tracers, Supplier<String> built, boolean walksTree) {

    /** The values of {@code --accel}, of which {@link #choose} makes a {@link Kind}. */
    enum Choice { auto, none, bvh, grid }

    /** What a run finds its hits with, and how the progress line names its building. */
    enum Kind {
        LOOP("the paper's loop: nothing to build"),
        BVH("building the BVH"),
        GRID("building the view grid"),
        GRID_AND_BVH("building the view grid, the lights' grids and the BVH");

        final String building;

        Kind(String building) {
            this.building = building;
        }
    }

    /**
     * What {@code accel} asks for {@code scene}: {@code none} the paper's loop (Listing 4.3), as does a scene without
     * objects; {@code auto} and {@code grid} the view grid for the camera's rays, and for a scene with lights a grid
     * seen from each light for its shadow rays and the BVH for the rest; {@code bvh}, or a camera the grid cannot
     * serve, the BVH. The grid serves either camera at any number of samples.
     */
    static Kind choose(Scene scene, Choice accel) {
        if (accel == Choice.none || scene.objects().isEmpty()) {
            return Kind.LOOP;
        }
        boolean gridFits = ViewGrid.fits(scene); // both cameras: false only for a camera added later
        if (accel != Choice.bvh && gridFits) {
            return scene.lights().isEmpty() ? Kind.GRID : Kind.GRID_AND_BVH;
        }
        return Kind.BVH;
    }

    /** {@link #build} of what {@code accel} asks ({@link #choose}), from nothing. */
    static Accelerator of(Scene scene, Choice accel, int width, int height, int samples, int threads) {
        return build(choose(scene, accel), scene, width, height, samples, threads, new StructureCache());
    }

    /** Builds {@code kind} for {@code scene}; the BVH and the light grids from {@code kept} where they still serve. */
    static Accelerator build(Kind kind, Scene scene, int width, int height, int samples, int threads,
            StructureCache kept) {
        switch (kind) {
            case GRID -> {
                ViewGrid grid = ViewGrid.build(scene, width, height, samples, threads);
                return new Accelerator(grid::newTracer, () -> describe(grid), false);
            }
            case GRID_AND_BVH -> {
                // the BVH on a thread of its own: each structure has passes on one thread, which the other's fill
                CompletableFuture<Bvh> tree = CompletableFuture.supplyAsync(() -> kept.bvh(scene), runnable -> {
                    Thread thread = new Thread(runnable, "rtd-build");
                    thread.setDaemon(true);
                    thread.start();
                });
                ViewGrid grid = ViewGrid.build(scene, width, height, samples, threads);
                LightGrids lights = kept.lightGrids(scene, width, height, samples, threads);
                Bvh bvh = join(tree);
                return new Accelerator(() -> grid.newTracer(lights.newTracer(bvh.newTracer())), () -> describe(grid)
                        + ", " + (lights.count() == 0 ? "no light grid"
                                : StatsReport.count(lights.count(), "light grid") + " of "
                                + StatsReport.count(lights.entries(), "entry", "entries")) + ", and BVH of "
                        + StatsReport.count(bvh.nodeCount(), "node"), true);
            }
            case BVH -> {
                Bvh bvh = kept.bvh(scene);
                return new Accelerator(bvh::newTracer, () -> "BVH of " + StatsReport.count(bvh.nodeCount(), "node"), true);
            }
            default -> {
                return new Accelerator(() -> new LinearTracer(scene), () -> "no BVH: the paper's loop tests every object",
                        false);
            }
        }
    }

    private static String describe(ViewGrid grid) {
        return String.format(Locale.ROOT, "view grid of %s of %d × %d pixels, %s", StatsReport.count(grid.cellCount(),
                "cell"), grid.cellSide(), grid.cellSide(), StatsReport.count(grid.entries(), "entry", "entries"));
    }

    /** What {@code built} built, or what it threw. */
    private static <T> T join(CompletableFuture<T> built) {
        try {
            return built.join();
        } catch (CompletionException e) {
            if (e.getCause() instanceof RuntimeException runtime) {
                throw runtime;
            }
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw e;
        }
    }
}
