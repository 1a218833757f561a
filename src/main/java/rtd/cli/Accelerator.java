package rtd.cli;

import java.util.List;
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
 * What a run finds its hits with, as {@code --accel} chose and built it: a new tracer for each thread, what was built
 * for {@code --stats} (made only if asked: formatting numbers the first time is slow), and whether the tracers walk a
 * tree, so that nodes per ray mean something.
 */
record Accelerator(Supplier<Tracer> tracers, Supplier<String> built, boolean walksTree) {

    enum Choice { auto, none, bvh, grid }

    /**
     * The fewest objects for which {@code auto} and {@code grid} take the image of hits for a flat picture: below, the
     * view grid, whose rays test fewer objects, builds as fast.
     */
    static final int IMAGE_THRESHOLD = 100_000;

    /**
     * The fewest objects for which {@code auto} builds the lights' and the mirrors' grids: fewer fit in one leaf of the
     * BVH, whose shadow and mirrored rays test them all sooner than a grid finds a ray's cell.
     */
    static final int POINT_GRIDS_THRESHOLD = 16;

    /** What a run finds its hits with, and how the progress line names its building. */
    enum Kind {
        LOOP("the paper's loop: nothing to build"),
        BVH("building the BVH"),
        GRID("building the view grid"),
        GRID_BVH_AND_POINT_GRIDS("building the view grid, the lights' and mirrors' grids and the BVH"),
        GRID_AND_BVH("building the view grid and the BVH"),
        IMAGE("finding each pixel's hit, object by object");

        final String building;

        Kind(String building) {
            this.building = building;
        }

        /** Whether the camera's rays go to a view grid. */
        boolean viewGrid() {
            return this == GRID || this == GRID_AND_BVH || this == GRID_BVH_AND_POINT_GRIDS;
        }
    }

    /**
     * What {@code accel} asks for {@code scene}: {@code none} (or no objects) the paper's loop (Listing 4.3);
     * {@code auto} and {@code grid} the view grid, with lights also the BVH and a grid from each light and mirror,
     * which {@code auto} leaves out for fewer than {@link #POINT_GRIDS_THRESHOLD} objects; {@code bvh}, or a camera the
     * grid cannot serve, the BVH.
     */
    static Kind choose(Scene scene, Choice accel) {
        if (accel == Choice.none || scene.objects().isEmpty()) {
            return Kind.LOOP;
        }
        if (accel == Choice.bvh || !ViewGrid.fits(scene)) { // fits both cameras: false only for a camera added later
            return Kind.BVH;
        }
        if (scene.lights().isEmpty()) {
            return Kind.GRID;
        }
        boolean few = accel == Choice.auto && scene.objects().size() < POINT_GRIDS_THRESHOLD;
        return few ? Kind.GRID_AND_BVH : Kind.GRID_BVH_AND_POINT_GRIDS;
    }

    /**
     * As above, for a {@code width × height} picture of {@code samples²} rays a pixel: where that takes the view grid
     * alone, a picture of one ray a pixel of {@link #IMAGE_THRESHOLD} objects or more takes the image of hits, if it
     * {@link HitImage#pays}.
     */
    static Kind choose(Scene scene, Choice accel, int width, int height, int samples) {
        Kind kind = choose(scene, accel);
        return kind == Kind.GRID && samples == 1 && scene.objects().size() >= IMAGE_THRESHOLD
                && HitImage.pays(scene, width, height) ? Kind.IMAGE : kind;
    }

    /** {@link #build} of what {@code accel} asks, from nothing. */
    static Accelerator of(Scene scene, Choice accel, int width, int height, int samples, int threads) {
        return build(choose(scene, accel, width, height, samples), scene, width, height, samples, threads,
                new StructureCache());
    }

    /** Builds {@code kind} for {@code scene}; the BVH and the light grids from {@code kept} where they still serve. */
    static Accelerator build(Kind kind, Scene scene, int width, int height, int samples, int threads,
            StructureCache kept) {
        if (kind == Kind.LOOP) {
            return new Accelerator(() -> new LinearTracer(scene), () -> "no BVH: the paper's loop tests every object",
                    false);
        }
        if (kind == Kind.BVH) {
            Bvh bvh = kept.bvh(scene);
            return new Accelerator(bvh::newTracer, () -> "BVH of " + StatsReport.count(bvh.nodeCount(), "node"), true);
        }
        if (kind == Kind.IMAGE) {
            HitImage image = HitImage.build(scene, width, height, threads);
            return new Accelerator(image::newTracer, () -> String.format(Locale.ROOT, "image of hits in %s of %d × %d "
                    + "pixels, %s", StatsReport.count(image.tileCount(), "tile"), image.tileSide(), image.tileSide(),
                    StatsReport.count(image.entries(), "entry", "entries")), false);
        }
        // the BVH on a thread of its own: each structure has passes on one thread, which the other's fill
        CompletableFuture<Bvh> tree = kind == Kind.GRID ? null : CompletableFuture.supplyAsync(() -> kept.bvh(scene),
                runnable -> {
                    Thread thread = new Thread(runnable, "rtd-build");
                    thread.setDaemon(true);
                    thread.start();
                });
        ViewGrid grid = ViewGrid.build(scene, width, height, samples, threads);
        if (tree == null) {
            return new Accelerator(grid::newTracer, () -> describe(grid), false);
        }
        boolean pointGrids = kind == Kind.GRID_BVH_AND_POINT_GRIDS;
        LightGrids lights = pointGrids ? kept.lightGrids(scene, width, height, samples, threads) : LightGrids.NONE;
        MirrorGrids mirrors = pointGrids // the camera's: never kept
                ? MirrorGrids.build(scene, width, height, samples, threads) : MirrorGrids.NONE;
        Bvh bvh = join(tree);
        return new Accelerator(() -> grid.newTracer(lights.newTracer(mirrors.newTracer(bvh.newTracer()))),
                () -> describe(grid) + ", " + (lights.count() == 0 ? "no light grid"
                        : StatsReport.count(lights.count(), "light grid") + " of "
                                + StatsReport.count(lights.entries(), "entry", "entries"))
                        + (mirrors.count() == 0 ? "" : ", " + StatsReport.count(mirrors.count(), "mirror grid") + " of "
                                + StatsReport.count(mirrors.entries(), "entry", "entries"))
                        + ", and BVH of " + StatsReport.count(bvh.nodeCount(), "node"), true);
    }

    private static String describe(ViewGrid grid) {
        return String.format(Locale.ROOT, "view grid of %s of %d × %d pixels, %s", StatsReport.count(grid.cellCount(),
                "cell"), grid.cellSide(), grid.cellSide(), StatsReport.count(grid.entries(), "entry", "entries"));
    }

    private static <T> T join(CompletableFuture<T> built) {
        try {
            return built.join();
        } catch (CompletionException e) {
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw e.getCause() instanceof RuntimeException runtime ? runtime : e;
        }
    }

    /**
     * The structures of a run's frames that do not depend on the camera, kept from one frame to the next: the BVH
     * while the objects equal the last frame's, the light grids while objects and lights do. A shape that is no
     * record (a mesh's triangle) equals only itself, so it is built anew; every pixel is the one a fresh build gives.
     */
    static final class StructureCache {

        private final Last<Bvh> bvh = new Last<>();
        private final Last<LightGrids> lightGrids = new Last<>();

        Bvh bvh(Scene scene) {
            return bvh.get(scene.objects(), () -> Bvh.build(scene));
        }

        LightGrids lightGrids(Scene scene, int width, int height, int samples, int threads) {
            return lightGrids.get(List.of(scene.objects(), scene.lights(), width, height, samples),
                    () -> LightGrids.build(scene, width, height, samples, threads));
        }

        /** The last value built and what it was built for; its own lock, so that two structures build side by side. */
        private static final class Last<V> {
            private List<?> key;
            private V value;

            synchronized V get(List<?> wanted, Supplier<V> build) {
                if (value == null || !wanted.equals(key)) {
                    key = null;
                    value = null; // the old structure and its objects may go before the new one is built
                    value = build.get();
                    key = wanted;
                }
                return value;
            }
        }
    }
}
