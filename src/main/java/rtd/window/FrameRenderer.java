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

/**
 * Renders one frame of the window, pass by pass ({@link Refinement}), on all cores with {@link ParallelRenderer}: in
 * the picture's colours as {@code -o} shades them (flat, or {@link WhittedShader} with lights), or a debug view
 * ({@link ViewShader}) with its legend. A coarse pass renders one ray per block ({@link BlockCamera}) with the tracers
 * for any camera; the full pass, with those {@code -o} builds for the camera, its pixels are {@code -o}'s.
 *
 * <p>A coarse pass's pixel fills its whole block, so the picture shows at once and sharpens; the last pass, blocks of 1,
 * sets every pixel itself.
 *
 * <p>A render is cancelled by interrupting its thread: it then stops at the next band of rows, and shows nothing more.
 */
final class FrameRenderer {

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
     * The passes of one render, as the sides of their blocks: a new scene or camera starts coarse and is refined
     * ({@link #STILL}: 8, 4, 2, 1 pixels); while the camera moves, each frame renders at the moving resolution alone
     * ({@link #MOVING}: a quarter of the pixels, coarser for a scene too slow for that: {@link #moving}); once the
     * mouse rests, the full picture follows ({@link #RESTED}).
     *
     * @param blocks the sides of the blocks, coarsest first
     */
    record Refinement(List<Integer> blocks) {

        /** The time a moving frame may take: 15 frames per second, smooth enough to follow the mouse. */
        static final long FRAME_NANOS = 1_000_000_000L / 15;
        static final Refinement STILL = new Refinement(List.of(8, 4, 2, 1));
        static final Refinement MOVING = new Refinement(List.of(2));
        static final Refinement RESTED = new Refinement(List.of(1));

        Refinement {
            blocks = List.copyOf(blocks);
        }

        /**
         * The moving frame after one of blocks of {@code block} pixels that took {@code nanos}: blocks of 2 if their
         * rays would fit in {@link #FRAME_NANOS}, else blocks of 4 if theirs would, else 8; so a heavy scene still
         * follows the mouse. Before any moving frame ({@code nanos} 0), blocks of 2.
         */
        static Refinement moving(int block, long nanos) {
            int next = 2;
            while (next < 8 && nanos * ((double) block * block) / (next * next) > FRAME_NANOS) {
                next *= 2; // a quarter of the rays, about a quarter of the time
            }
            return next == 2 ? MOVING : new Refinement(List.of(next));
        }

        boolean endsFull() {
            return blocks.get(blocks.size() - 1) == 1;
        }
    }

    /** One frame to render: {@code view} null for the picture. */
    record Frame(Scene scene, View view, int width, int height, int samples, int threads, Refinement refinement) {
    }

    /**
     * A coarse pass's camera: pixel (x, y) of the small picture of a {@code block}-pixel grid is the ray of pixel
     * {@code (x·block, y·block)} of the full {@code width × height} picture, made by the scene's camera: so a block
     * shows the colour its top left pixel will have.
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

    FrameRenderer(Engine engine) {
        this.engine = engine;
    }

    /**
     * Renders {@code frame}'s passes, handing each to {@code listener} as it is done, with {@code anyCamera}'s tracers
     * for the coarse passes; returns false if it was cancelled.
     */
    boolean render(Frame frame, Supplier<Tracer> anyCamera, Consumer<Pass> listener) {
        for (int block : frame.refinement().blocks()) {
            long start = System.nanoTime();
            RenderResult result;
            try {
                result = pass(frame, block, anyCamera);
            } catch (IllegalStateException e) {
                if (Thread.currentThread().isInterrupted()) {
                    return false; // cancelled by a newer render
                }
                throw e;
            }
            if (Thread.currentThread().isInterrupted()) {
                return false; // one thread stops at the next band and returns what it has: not to be shown
            }
            Picture picture = filled(block, result.image(), frame.width(), frame.height());
            listener.accept(shown(frame, picture, block, System.nanoTime() - start, result.work().rays()));
        }
        return true;
    }

    private RenderResult pass(Frame frame, int block, Supplier<Tracer> anyCamera) {
        Scene scene = frame.scene();
        int w = blocks(frame.width(), block);
        int h = blocks(frame.height(), block);
        if (block == 1) {
            int samples = frame.view() == null ? frame.samples() : 1; // a view takes one ray per pixel
            Supplier<Tracer> tracers = engine.forPicture(scene, frame.width(), frame.height(), samples, anyCamera);
            return ParallelRenderer.render(scene.camera(), tracers, shaders(scene, frame.view()), w, h, samples,
                    frame.threads(), new RenderProgress());
        }
        BlockCamera camera = new BlockCamera(scene.camera(), block, frame.width(), frame.height());
        return ParallelRenderer.render(camera, anyCamera, shaders(scene, frame.view()), w, h, 1, frame.threads(),
                new RenderProgress());
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
    private static Pass shown(Frame frame, Picture picture, int block, long nanos, long rays) {
        if (frame.view() == null) {
            return new Pass(picture, block, nanos, rays, "");
        }
        ViewPicture view = ViewPicture.of(frame.view(), picture, frame.scene());
        return new Pass(view.picture(), block, nanos, rays, view.report());
    }
}
