package rtd.window;

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
 * <p>A render is cancelled by interrupting its thread: it then stops at the next band of rows, and shows nothing more.
 */
final class FrameRenderer {

    /** What a pass shows: the picture (or the view with its legend), how long the pass took and its rays. */
    record Pass(Picture picture, int block, long nanos, long rays, String legend) {
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
     * Renders {@code frame}'s passes into {@code buffer}, handing each to {@code listener} as it is done, with
     * {@code anyCamera}'s tracers for the coarse passes; returns false if it was cancelled.
     */
    boolean render(Frame frame, Supplier<Tracer> anyCamera, ProgressiveBuffer buffer, Consumer<Pass> listener) {
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
            buffer.put(block, result.image());
            listener.accept(shown(frame, buffer, block, System.nanoTime() - start, result.work().rays()));
        }
        return true;
    }

    private RenderResult pass(Frame frame, int block, Supplier<Tracer> anyCamera) {
        Scene scene = frame.scene();
        int w = ProgressiveBuffer.blocks(frame.width(), block);
        int h = ProgressiveBuffer.blocks(frame.height(), block);
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

    /** The buffer as the window shows it: a view's numbers turned into colours, with its legend below. */
    private static Pass shown(Frame frame, ProgressiveBuffer buffer, int block, long nanos, long rays) {
        if (frame.view() == null) {
            return new Pass(buffer.picture(), block, nanos, rays, "");
        }
        ViewPicture view = ViewPicture.of(frame.view(), buffer.picture(), frame.scene());
        return new Pass(view.picture(), block, nanos, rays, view.report());
    }
}
