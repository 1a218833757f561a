package rtd.accel;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.Executor;
import java.util.function.Supplier;
import rtd.render.LinearTracer;
import rtd.render.Tracer;
import rtd.render.WorkCount;
import rtd.scene.Scene;

/**
 * The engine's one door: which of its structures answer which rays for {@code --accel}, and those structures built.
 * An accelerator is what a run finds its hits with: a new tracer for each thread, what was built for
 * {@code --stats} (made only if asked: formatting numbers the first time is slow), and whether the tracers walk a
 * tree, so that nodes per ray mean something. Every tracer finds the paper's loop's hit (Listing 4.3), bit for bit.
 */
public record Accelerator(Supplier<Tracer> tracers, Supplier<String> built, boolean walksTree) {

    /** What {@code --accel} asks: the choice by the scene, the paper's loop, the BVH for every ray, the grids. */
    public enum Choice { auto, none, bvh, grid }

    /**
     * The fewest objects for which {@code auto} and {@code grid} take the image of hits for a flat picture: below, the
     * view grid, whose rays test fewer objects, builds as fast.
     */
    public static final int IMAGE_THRESHOLD = 100_000;

    /**
     * The fewest objects for which {@code auto} builds the lights' grids: fewer fit in one leaf of the BVH, whose
     * shadow rays test them all sooner than a grid finds a ray's cell.
     */
    public static final int LIGHT_GRIDS_THRESHOLD = 16;

    /** What a run finds its hits with, and how the progress line names its building. */
    public enum Kind {
        LOOP("the paper's loop: nothing to build"),
        BVH("building the BVH"),
        GRID("building the view grid"),
        GRID_BVH_AND_LIGHT_GRIDS("building the view grid, the lights' grids and the BVH"),
        GRID_AND_BVH("building the view grid and the BVH"),
        IMAGE("finding each pixel's hit, object by object");

        private final String building;

        Kind(String building) {
            this.building = building;
        }

        /** What the progress line says while this is built. */
        public String building() {
            return building;
        }

        /** Whether the camera's rays go to a view grid. */
        public boolean viewGrid() {
            return this == GRID || this == GRID_AND_BVH || this == GRID_BVH_AND_LIGHT_GRIDS;
        }
    }

    /**
     * What {@code accel} asks for {@code scene}: {@code none} (or no objects) the paper's loop (Listing 4.3);
     * {@code auto} and {@code grid} the view grid, with lights also the BVH and a grid from each light, which
     * {@code auto} leaves out for fewer than {@link #LIGHT_GRIDS_THRESHOLD} objects; {@code bvh}, or a camera the
     * grid cannot serve, the BVH.
     */
    public static Kind choose(Scene scene, Choice accel) {
        if (accel == Choice.none || scene.objects().isEmpty()) {
            return Kind.LOOP;
        }
        if (accel == Choice.bvh || !ViewGrid.fits(scene)) { // fits both cameras: false only for a camera added later
            return Kind.BVH;
        }
        if (scene.lights().isEmpty()) {
            return Kind.GRID;
        }
        boolean few = accel == Choice.auto && scene.objects().size() < LIGHT_GRIDS_THRESHOLD;
        return few ? Kind.GRID_AND_BVH : Kind.GRID_BVH_AND_LIGHT_GRIDS;
    }

    /**
     * As above, for a {@code width × height} picture of {@code samples²} rays a pixel: where that takes the view grid
     * alone, a picture of one ray a pixel of {@link #IMAGE_THRESHOLD} objects or more takes the image of hits, if it
     * {@link HitImage#pays}.
     */
    public static Kind choose(Scene scene, Choice accel, int width, int height, int samples) {
        Kind kind = choose(scene, accel);
        return kind == Kind.GRID && samples == 1 && scene.objects().size() >= IMAGE_THRESHOLD
                && HitImage.pays(scene, width, height) ? Kind.IMAGE : kind;
    }

    /** {@link #build} of what {@code accel} asks, from nothing. */
    public static Accelerator of(Scene scene, Choice accel, int width, int height, int samples, int threads) {
        return build(choose(scene, accel, width, height, samples), scene, width, height, samples, threads,
                new StructureCache());
    }

    /** Builds {@code kind} for {@code scene}; the BVH and the light grids from {@code kept} where they still serve. */
    public static Accelerator build(Kind kind, Scene scene, int width, int height, int samples, int threads,
            StructureCache kept) {
        if (kind == Kind.LOOP) {
            return new Accelerator(() -> new LinearTracer(scene), () -> "no BVH: the paper's loop tests every object",
                    false);
        }
        if (kind == Kind.BVH) {
            Bvh bvh = kept.bvh(scene);
            return new Accelerator(bvh::newTracer, () -> "BVH of " + WorkCount.count(bvh.nodeCount(), "node"), true);
        }
        if (kind == Kind.IMAGE) {
            HitImage image = HitImage.build(scene, width, height, threads);
            return new Accelerator(image::newTracer, () -> String.format(Locale.ROOT, "image of hits in %s of %d × %d "
                    + "pixels, %s", WorkCount.count(image.tileCount(), "tile"), image.tileSide(), image.tileSide(),
                    WorkCount.count(image.entries(), "entry", "entries")), false);
        }
        CompletableFuture<Bvh> tree = kind == Kind.GRID ? null
                : CompletableFuture.supplyAsync(() -> kept.bvh(scene), beside(threads));
        ViewGrid grid = ViewGrid.build(scene, width, height, samples, threads);
        if (tree == null) {
            return new Accelerator(grid::newTracer, () -> describe(grid), false);
        }
        LightGrids lights = kind == Kind.GRID_BVH_AND_LIGHT_GRIDS
                ? kept.lightGrids(scene, width, height, samples, threads) : LightGrids.NONE;
        Bvh bvh = join(tree);
        return new Accelerator(() -> grid.newTracer(lights.newTracer(bvh.newTracer())),
                () -> describe(grid) + ", " + (lights.count() == 0 ? "no light grid"
                        : WorkCount.count(lights.count(), "light grid") + " of "
                                + WorkCount.count(lights.entries(), "entry", "entries"))
                        + ", and BVH of " + WorkCount.count(bvh.nodeCount(), "node"), true);
    }

    /**
     * The window's tracers for the picture of one camera: its view grid before {@code anyCamera}'s, where
     * {@code accel} takes a view grid for {@code scene}; else {@code anyCamera}'s.
     */
    public static Supplier<Tracer> forPicture(Choice accel, Scene scene, int width, int height, int samples,
            int threads, Supplier<Tracer> anyCamera) {
        if (!choose(scene, accel).viewGrid()) {
            return anyCamera;
        }
        ViewGrid grid = ViewGrid.build(scene, width, height, samples, threads);
        return () -> grid.newTracer(anyCamera.get());
    }

    /**
     * The window's tracers for any camera, chained as for a picture without its view grid (which answers only its
     * camera's rays): the lights' grids before the BVH, the BVH, or the paper's loop; the BVH and the light grids
     * from {@code kept} while they still serve.
     */
    public static Supplier<Tracer> forAnyCamera(Choice accel, Scene scene, int width, int height, int threads,
            StructureCache kept) {
        Kind kind = choose(scene, accel);
        if (kind != Kind.GRID_BVH_AND_LIGHT_GRIDS) {
            return build(kind == Kind.LOOP ? kind : Kind.BVH, scene, width, height, 1, threads, kept).tracers();
        }
        Bvh bvh = kept.bvh(scene);
        LightGrids lights = kept.lightGrids(scene, width, height, 1, threads);
        return () -> lights.newTracer(bvh.newTracer());
    }

    /**
     * Where the BVH is built beside the grids: on a thread of its own, as each structure has passes on one thread,
     * which the other's fill; on the calling thread, first, if the run has one thread ({@code --threads 1}).
     */
    static Executor beside(int threads) {
        return threads == 1 ? Runnable::run : runnable -> {
            Thread thread = new Thread(runnable, "rtd-build");
            thread.setDaemon(true);
            thread.start();
        };
    }

    private static String describe(ViewGrid grid) {
        return String.format(Locale.ROOT, "view grid of %s of %d × %d pixels, %s", WorkCount.count(grid.cellCount(),
                "cell"), grid.cellSide(), grid.cellSide(), WorkCount.count(grid.entries(), "entry", "entries"));
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
    public static final class StructureCache {

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
