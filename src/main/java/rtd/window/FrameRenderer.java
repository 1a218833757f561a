package rtd.window;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.FutureTask;
import java.util.function.BiConsumer;
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
 * Renders the window's frames pass by pass on all cores with {@link ParallelRenderer}, shaded as {@code -o} (flat, or
 * {@link WhittedShader} with lights) or as a view ({@link ViewShader}) with its legend. A pass is the side of its
 * blocks: a new scene or camera starts coarse and is refined ({@link #STILL}), a moving camera's frames take one coarse
 * pass ({@link #moving}), a resting one the full picture ({@link #RESTED}). A coarse pass traces each block's top left
 * pixel's own ray ({@link BlockCamera}) with the tracers for any camera and fills the block with it; the full pass,
 * with the tracers {@code -o} builds for the camera, is {@code -o}'s picture.
 *
 * <p>Frames render on a thread of their own, the newest asked for: one still waiting is dropped for a newer one, and a
 * frame that ends in full cancels the one in progress (its render stops at the next band of rows and shows nothing
 * more), so the picture follows the latest camera and the window's thread never waits; a moving frame waits for the
 * one before, so that frames are finished and shown.
 */
final class FrameRenderer implements AutoCloseable {

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

    private final WindowSetup setup;
    private final Executor ui;
    private final BiConsumer<Pass, Boolean> shown;
    private final Consumer<RuntimeException> failed;
    private final ExecutorService thread = Executors.newSingleThreadExecutor(job -> daemon(job, "rtd-window-render"));
    /** Counts the frames asked for: one that is not the newest when its turn comes is dropped. */
    private long asked;
    private Future<?> running = new FutureTask<>(() -> null);
    private long shownFrame = -1;
    /** The next moving frame's blocks, from the blocks and time of the last moving frame shown. */
    private List<Integer> nextMoving = MOVING;
    /** The tracers for any camera in {@link #traced}'s objects and lights, built again only for another scene. */
    private Scene traced;
    private Supplier<Tracer> anyCamera;

    /**
     * Frames of {@code setup}'s size, samples and threads, each pass handed to {@code shown} on {@code ui} with whether
     * its frame is the newest asked for; a render's failure (a bug, not a cancel) goes to {@code failed}.
     */
    FrameRenderer(WindowSetup setup, Executor ui, BiConsumer<Pass, Boolean> shown, Consumer<RuntimeException> failed) {
        this.setup = setup;
        this.ui = ui;
        this.shown = shown;
        this.failed = failed;
    }

    /**
     * Asks for a frame of {@code file}'s objects and lights seen by {@code camera} ({@code view} null for the picture)
     * in passes of {@code blocks}, or for a moving frame ({@code blocks} null), coarser if the last was too slow.
     */
    synchronized void frame(Scene file, ICamera camera, View view, List<Integer> blocks) {
        boolean moving = blocks == null;
        List<Integer> passes = moving ? nextMoving : blocks;
        long frame = asked + 1;
        submit(() -> render(file, camera, view, passes, pass -> ui.execute(() -> show(frame, pass, moving))), !moving);
    }

    /** A pass on the window's thread; passes come in the order they were rendered, so none is older than the last. */
    private void show(long frame, Pass pass, boolean moving) {
        if (moving) {
            nextMoving = moving(pass.block(), pass.nanos());
        }
        shownFrame = frame;
        shown.accept(pass, newest());
    }

    /** Whether the frame shown last is the newest asked for. */
    synchronized boolean newest() {
        return shownFrame == asked;
    }

    /**
     * Runs {@code job} next on the render thread, in place of any job still waiting; {@code cancel}s the running one.
     */
    synchronized void submit(Runnable job, boolean cancel) {
        if (thread.isShutdown()) {
            return; // the window is closed
        }
        long mine = ++asked;
        if (cancel) {
            running.cancel(true);
        }
        thread.execute(() -> run(mine, job));
    }

    private void run(long mine, Runnable job) {
        FutureTask<Void> task = new FutureTask<>(() -> {
            try {
                job.run();
            } catch (RuntimeException e) {
                if (!Thread.currentThread().isInterrupted()) {
                    failed.accept(e); // a bug; the next frame renders as usual
                }
            }
        }, null);
        synchronized (this) {
            if (mine != asked) {
                return; // a newer job waits
            }
            running = task; // a cancel interrupts this thread only while the task runs
        }
        task.run();
        if (!task.isCancelled()) {
            try {
                task.get();
            } catch (ExecutionException e) { // an Error, such as running out of memory: told, as on any thread
                Thread.currentThread().getUncaughtExceptionHandler().uncaughtException(Thread.currentThread(),
                        e.getCause());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Stops the render thread: the frame in progress is interrupted, and no other renders. */
    @Override
    public void close() {
        thread.shutdownNow();
    }

    /** A daemon thread named {@code name} that runs {@code job}: the window's threads never keep Java running. */
    static Thread daemon(Runnable job, String name) {
        Thread thread = new Thread(job, name);
        thread.setDaemon(true);
        return thread;
    }

    /**
     * Renders {@code file}'s objects and lights seen by {@code camera} ({@code view} null for the picture) in passes
     * of {@code blocks}, handing each to {@code listener} as it is done; interrupted, it stops. One thread at a time.
     */
    void render(Scene file, ICamera camera, View view, List<Integer> blocks, Consumer<Pass> listener) {
        if (traced != file) {
            anyCamera = setup.engine().forAnyCamera(file, setup.width(), setup.height());
            traced = file;
        }
        Scene scene = new Scene(file.ambient(), camera, file.objects(), file.lights());
        for (int block : blocks) {
            long start = System.nanoTime();
            RenderResult result = pass(scene, view, block); // interrupted, it throws or returns what it has
            if (Thread.currentThread().isInterrupted()) {
                return; // cancelled by a newer render: nothing more to show
            }
            Picture picture = filled(block, result.image(), setup.width(), setup.height());
            listener.accept(shown(scene, view, picture, block, System.nanoTime() - start, result.work().rays()));
        }
    }

    private RenderResult pass(Scene scene, View view, int block) {
        int w = setup.width();
        int h = setup.height();
        if (block == 1) {
            int rays = view == null ? setup.samples() : 1; // a view takes one ray per pixel
            return ParallelRenderer.render(scene.camera(), setup.engine().forPicture(scene, w, h, rays, anyCamera),
                    shaders(scene, view), w, h, rays, setup.threads(), new RenderProgress());
        }
        return ParallelRenderer.render(new BlockCamera(scene.camera(), block, w, h), anyCamera, shaders(scene, view),
                blocks(w, block), blocks(h, block), 1, setup.threads(), new RenderProgress());
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
