package rtd.window;

import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import rtd.camera.ICamera;
import rtd.image.Picture;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.render.Shader;
import rtd.render.Tracer;
import rtd.scene.Scene;
import rtd.shade.FlatShader;
import rtd.shade.WhittedShader;
import rtd.view.View;
import rtd.view.ViewPicture;
import rtd.view.ViewShader;
import rtd.window.WindowSetup.Engine;

/**
 * Renders the window's frames pass by pass on all cores with {@link ParallelRenderer}: in the picture's colours as
 * {@code -o} shades them (flat, or {@link WhittedShader} with lights), or a debug view ({@link ViewShader}) with its
 * legend. A pass is the side of its blocks: a new scene or camera starts coarse and is refined ({@link #STILL}: 8, 4,
 * 2, 1 pixels); while the camera moves, each frame renders at the moving resolution alone ({@link #moving}); once the
 * mouse rests, the full picture follows ({@link #RESTED}). A coarse pass traces one ray per block, its top left pixel's
 * own ({@link BlockCamera}), with the tracers for any camera, and that colour fills the block, so the picture shows at
 * once and sharpens; the full pass, with the tracers {@code -o} builds for the camera, is {@code -o}'s picture.
 *
 * <p>A render is cancelled by interrupting its thread: it then stops at the next band of rows, and shows nothing more.
 */
final class FrameRenderer {

    static final List<Integer> STILL = List.of(8, 4, 2, 1);
    static final List<Integer> MOVING = List.of(2);
    static final List<Integer> RESTED = List.of(1);
    /** The time a moving frame may take: 15 frames per second, smooth enough to follow the mouse. */
    static final long FRAME_NANOS = 1_000_000_000L / 15;

    /** What a pass shows: the picture (or the view with its legend), how long the pass took and its rays. */
    record Pass(Picture picture, int block, long nanos, long rays, String legend) {

        /**
         * The window's status line for this pass of a {@code width × height} frame: {@code shows} "picture" or a
         * view's name (and the clock), its time, rays per second, how coarse it is still, and {@code pixel} (the
         * one under the mouse, or null).
         */
        String status(int width, int height, int[] pixel, String shows) {
            double seconds = nanos / 1e9;
            String rate = seconds > 0 ? String.format(Locale.ROOT, "%.2f Mrays/s", rays / seconds / 1e6) : "–";
            String blocks = block > 1 ? String.format(Locale.ROOT, " (blocks of %d × %d)", block, block) : "";
            String under = pixel == null ? "" : String.format(Locale.ROOT, " · pixel (%d, %d)", pixel[0], pixel[1]);
            return String.format(Locale.ROOT, "%s · %d × %d%s · last frame %.3f s · %s%s", shows, width, height,
                    blocks, seconds, rate, under);
        }
    }

    /**
     * A coarse pass's camera: pixel (x, y) of the small picture of a {@code block}-pixel grid is the ray of pixel
     * {@code (x·block, y·block)} of the full {@code width × height} picture, made by the scene's camera.
     */
    private record BlockCamera(ICamera full, int block, int width, int height) implements ICamera {

        @Override
        public Ray generateRay(int x, int y, int w, int h) {
            return full.generateRay(x * block, y * block, width, height);
        }

        @Override
        public Ray generateRay(float x, float y, int w, int h) {
            return full.generateRay(x * block, y * block, width, height);
        }

        @Override
        public Vector3f position() {
            return full.position();
        }
    }

    private final Engine engine;
    private final int width;
    private final int height;
    private final int samples;
    private final int threads;
    /** The tracers for any camera in {@link #traced}'s objects and lights, built again only for another scene. */
    private Scene traced;
    private Supplier<Tracer> anyCamera;

    /** Frames of {@code width × height} pixels, {@code samples × samples} rays each in full, on {@code threads}. */
    FrameRenderer(Engine engine, int width, int height, int samples, int threads) {
        this.engine = engine;
        this.width = width;
        this.height = height;
        this.samples = samples;
        this.threads = threads;
    }

    /**
     * Renders {@code file}'s objects and lights seen by {@code camera} ({@code view} null for the picture) in passes
     * of {@code blocks}, handing each to {@code listener} as it is done. On one thread at a time; interrupted, it stops.
     */
    void render(Scene file, ICamera camera, View view, List<Integer> blocks, Consumer<Pass> listener) {
        if (traced != file) {
            anyCamera = engine.forAnyCamera(file, width, height);
            traced = file;
        }
        Scene scene = new Scene(file.ambient(), camera, file.objects(), file.lights());
        for (int block : blocks) {
            long start = System.nanoTime();
            RenderResult result = pass(scene, view, block); // interrupted, it throws or returns what it has
            if (Thread.currentThread().isInterrupted()) {
                return; // cancelled by a newer render: nothing more to show
            }
            Picture picture = filled(block, result.image(), width, height);
            listener.accept(shown(scene, view, picture, block, System.nanoTime() - start, result.work().rays()));
        }
    }

    private RenderResult pass(Scene scene, View view, int block) {
        if (block == 1) {
            int rays = view == null ? samples : 1; // a view takes one ray per pixel
            return ParallelRenderer.render(scene.camera(), engine.forPicture(scene, width, height, rays, anyCamera),
                    shaders(scene, view), width, height, rays, threads, new RenderProgress());
        }
        return ParallelRenderer.render(new BlockCamera(scene.camera(), block, width, height), anyCamera,
                shaders(scene, view), blocks(width, block), blocks(height, block), 1, threads, new RenderProgress());
    }

    /**
     * The moving frame after one of blocks of {@code block} pixels that took {@code nanos}: blocks of 2 if their rays
     * would fit in {@link #FRAME_NANOS}, else blocks of 4 if theirs would, else 8; so a heavy scene still follows the
     * mouse. Before any moving frame ({@code nanos} 0), blocks of 2.
     */
    static List<Integer> moving(int block, long nanos) {
        int next = 2;
        while (next < 8 && nanos * ((double) block * block) / (next * next) > FRAME_NANOS) {
            next *= 2; // a quarter of the rays, about a quarter of the time
        }
        return List.of(next);
    }

    /** The shaders {@code -o} (or {@code --view}) takes for {@code scene}: one for each tracer. */
    static Function<Tracer, Shader> shaders(Scene scene, View view) {
        if (view != null) {
            ViewShader shader = new ViewShader(view, scene.objects());
            return tracer -> shader;
        }
        if (scene.lights().isEmpty()) {
            FlatShader flat = new FlatShader(scene);
            return tracer -> flat;
        }
        return tracer -> new WhittedShader(scene, tracer);
    }

    /** How many blocks of {@code block} pixels cover {@code size} pixels: the last block may be cut off. */
    static int blocks(int size, int block) {
        return (size + block - 1) / block;
    }

    /** The {@code width × height} picture whose every block of {@code block × block} pixels has its pixel of coarse. */
    static Picture filled(int block, Picture coarse, int width, int height) {
        if (block == 1) {
            return coarse; // the full pass: every pixel its own already
        }
        int[] rgb = new int[width * height];
        for (int y = 0; y < height; y++) {
            int row = y / block * coarse.width();
            for (int x = 0; x < width; x++) {
                rgb[y * width + x] = coarse.rgb()[row + x / block];
            }
        }
        return new Picture(width, height, rgb);
    }

    /** The pass as the window shows it: a view's numbers turned into colours, with its legend below. */
    private static Pass shown(Scene scene, View view, Picture picture, int block, long nanos, long rays) {
        if (view == null) {
            return new Pass(picture, block, nanos, rays, "");
        }
        ViewPicture shown = ViewPicture.of(view, picture, scene);
        return new Pass(shown.picture(), block, nanos, rays, shown.report());
    }
}
