package rtd.cli;

import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.function.Supplier;
import rtd.accel.Bvh;
import rtd.accel.HitImage;
import rtd.accel.LightGrids;
import rtd.accel.MirrorGrids;
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
     * The fewest objects for which {@code --accel auto} takes the image of hits for a flat picture:
     * it builds less than the view grid but tests more, and its new code is compiled while it
     * runs. Measured whole process against the view grid: 1,000 spheres 0.88 against 0.63 s (11
     * pairs), 100,000 spheres 1.06 against 1.02 s (9 pairs), 150,000 spheres 1.07 against 1.07 s
     * (9 pairs), 250,000 spheres 1.11 against 1.18 s (9 pairs) and a terrain of 250,632 triangles
     * 1.23 against 1.22 s (7 pairs), 500,000 spheres 1.50 against 1.55 s (7 pairs), a million
     * 1.87 against 2.04 s (7 pairs), the terrain of a million triangles 2.18 against 2.30 s (7 pairs).
     * Since the image's flat picture is a lookup (the thirteenth round): 30,000 spheres 0.91 against
     * 0.91 s, 100,000 spheres 0.92 against 0.99 s (9 pairs each).
     */
    static final int IMAGE_THRESHOLD = 100_000;

    /** What a run finds its hits with, and how the progress line names its building. */
    enum Kind {
        LOOP("the paper's loop: nothing to build"),
        BVH("building the BVH"),
        GRID("building the view grid"),
        GRID_AND_BVH("building the view grid, the lights' and mirrors' grids and the BVH"),
        IMAGE("finding each pixel's hit, object by object"),
        IMAGE_AND_BVH("finding each pixel's hit, and building the lights' and mirrors' grids and the BVH");

        final String building;

        Kind(String building) {
            this.building = building;
        }
    }

    /**
     * What {@code accel} asks for {@code scene}, drawn with {@code samples²} rays a pixel:
     * {@code auto} takes, for a scene of {@link #IMAGE_THRESHOLD} objects or more drawn in flat
     * colours with one ray a pixel, the image of hits; for any other scene of
     * {@link #GRID_THRESHOLD} objects or more the view grid, and for a
     * scene with lights a grid seen from each light for its shadow rays, one seen from the eye's
     * mirror image in each flat mirror for the rays it reflects, and the BVH for the
     * rest; else the BVH if it has objects. {@code image} takes the view grid where the image of
     * hits cannot serve (more rays a pixel). Measured: on the shaded benchmark the grid and the
     * BVH took 4.52–4.71 s where the BVH alone took 4.87–4.88 s, and with the light grids 3.96
     * against 4.75 s (5 pairs); the image of hits against the view grid in docs/performance.md,
     * the tenth round (faster for the flat benchmarks, slower for the shaded one).
     */
    static Kind choose(Scene scene, Accel accel, int samples) {
        int objects = scene.objects().size();
        boolean gridFits = ViewGrid.fits(scene); // both cameras: false only for a camera added later
        boolean large = objects >= GRID_THRESHOLD;
        boolean lit = !scene.lights().isEmpty();
        boolean huge = objects >= IMAGE_THRESHOLD;
        if ((accel == Accel.image || accel == Accel.auto && huge && !lit) && HitImage.fits(scene, samples)) {
            return lit ? Kind.IMAGE_AND_BVH : Kind.IMAGE;
        }
        if ((accel == Accel.grid || accel == Accel.image || accel == Accel.auto && large) && gridFits) {
            return lit ? Kind.GRID_AND_BVH : Kind.GRID;
        }
        return accel != Accel.none && objects > 0 ? Kind.BVH : Kind.LOOP;
    }

    /** {@link #build} of what {@code accel} asks ({@link #choose}). */
    static Accelerator of(Scene scene, Accel accel, int width, int height, int samples, int threads) {
        return build(choose(scene, accel, samples), scene, width, height, samples, threads);
    }

    /**
     * Builds {@code kind} for {@code scene}, for a {@code width × height} picture with
     * {@code samples²} rays per pixel, with {@code threads} threads.
     */
    static Accelerator build(Kind kind, Scene scene, int width, int height, int samples, int threads) {
        switch (kind) {
            case GRID -> {
                ViewGrid grid = ViewGrid.build(scene, width, height, samples, threads);
                return new Accelerator(grid::newTracer, () -> String.format(Locale.ROOT,
                        "view grid of %s of %d × %d pixels, %s", StatsReport.count(grid.cellCount(), "cell"),
                        grid.cellSide(), grid.cellSide(), StatsReport.count(grid.entries(), "entry", "entries")), false);
            }
            case GRID_AND_BVH -> {
                CompletableFuture<Bvh> tree = inBackground(() -> Bvh.build(scene, threads));
                ViewGrid grid = ViewGrid.build(scene, width, height, samples, threads);
                LightGrids lights = LightGrids.build(scene, width, height, samples, threads);
                MirrorGrids mirrors = MirrorGrids.build(scene, width, height, samples, threads);
                Bvh bvh = join(tree);
                return new Accelerator(() -> grid.newTracer(mirrors.newTracer(lights.newTracer(bvh.newTracer()))),
                        () -> String.format(Locale.ROOT, "view grid of %s of %d × %d pixels, %s, %s%s, and BVH of %s",
                                StatsReport.count(grid.cellCount(), "cell"), grid.cellSide(), grid.cellSide(),
                                StatsReport.count(grid.entries(), "entry", "entries"), describe(lights),
                                describe(mirrors), StatsReport.count(bvh.nodeCount(), "node")), true);
            }
            case IMAGE -> {
                HitImage image = HitImage.build(scene, width, height, threads);
                if (image == null) { // too many entries: the view grid instead
                    return build(Kind.GRID, scene, width, height, samples, threads);
                }
                return new Accelerator(image::newTracer, () -> describe(image), false);
            }
            case IMAGE_AND_BVH -> {
                HitImage image = HitImage.build(scene, width, height, threads);
                if (image == null) {
                    return build(Kind.GRID_AND_BVH, scene, width, height, samples, threads);
                }
                CompletableFuture<Bvh> tree = inBackground(() -> Bvh.build(scene, threads));
                LightGrids lights = LightGrids.build(scene, width, height, samples, threads);
                MirrorGrids mirrors = MirrorGrids.build(scene, width, height, samples, threads);
                Bvh bvh = join(tree);
                return new Accelerator(() -> image.newTracer(mirrors.newTracer(lights.newTracer(bvh.newTracer()))),
                        () -> describe(image) + ", " + describe(lights) + describe(mirrors) + ", and BVH of "
                                + StatsReport.count(bvh.nodeCount(), "node"), true);
            }
            case BVH -> {
                Bvh bvh = Bvh.build(scene, threads);
                return new Accelerator(bvh::newTracer, () -> "BVH of " + StatsReport.count(bvh.nodeCount(), "node"), true);
            }
            default -> {
                return new Accelerator(() -> new LinearTracer(scene), () -> "no BVH: the paper's loop tests every object",
                        false);
            }
        }
    }

    /** The image of hits, for {@code --stats}. */
    private static String describe(HitImage image) {
        return String.format(Locale.ROOT, "image of hits in %s of %d × %d pixels, %s",
                StatsReport.count(image.tileCount(), "tile"), image.tileSide(), image.tileSide(),
                StatsReport.count(image.entries(), "entry", "entries"));
    }

    /** The lights' grids, for {@code --stats}. */
    private static String describe(LightGrids lights) {
        return lights.count() == 0 ? "no light grid"
                : StatsReport.count(lights.count(), "light grid") + " of "
                        + StatsReport.count(lights.entries(), "entry", "entries");
    }

    /** The mirrors' grids, for {@code --stats}: nothing if there are none. */
    private static String describe(MirrorGrids mirrors) {
        return mirrors.count() == 0 ? ""
                : ", " + StatsReport.count(mirrors.count(), "mirror grid") + " of "
                        + StatsReport.count(mirrors.entries(), "entry", "entries");
    }

    /**
     * Starts {@code build} on a thread of its own, so that two structures are built side by side:
     * each has passes that run on one thread, which the other's fill. The shaded benchmark's
     * build took 0.74 instead of 0.82 s (medians of 5 pairs); each structure is the same as built
     * alone.
     */
    private static <T> CompletableFuture<T> inBackground(Supplier<T> build) {
        return CompletableFuture.supplyAsync(build, runnable -> {
            Thread thread = new Thread(runnable, "rtd-build");
            thread.setDaemon(true);
            thread.start();
        });
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
