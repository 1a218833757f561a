package rtd.render;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;
import java.util.function.Supplier;
import rtd.camera.ICamera;
import rtd.image.Rgb;
import rtd.image.Picture;

/**
 * Listing 4.2 on all cores: the same ray per pixel as {@link rtd.scene.Scene#render}, bands of {@value #TILE} rows
 * shared out among threads; a {@link Tracer} finds each ray's nearest hit, a {@link Shader} turns it into a colour.
 * Every pixel depends only on its own rays, so the picture is the same for any number of threads. A thread takes the
 * next band not yet taken (a slow band holds no other back) and hands its tracer one {@value #TILE} × {@value #TILE}
 * square of pixels at a time, whose neighbouring rays a tracer may trace together.
 */
public final class ParallelRenderer {

    /** The side of the squares of pixels handed to {@link Tracer#traceAll} together. */
    static final int TILE = 8;
    /** How many squares side by side the renderer asks about at once first ({@link Tracer#traceAtOnce}). */
    static final int RUN = 64;
    /** The golden section's smaller part, {@code (3 − √5) / 2}: each step of it lands in the largest gap left. */
    private static final double GOLDEN_SECTION = (3 - Math.sqrt(5)) / 2;

    private ParallelRenderer() {
    }

    /**
     * Renders a {@code width × height} image with {@code threads} threads, each with its own tracer from
     * {@code tracers} and a shader for it from {@code shaders}, counting finished rows in {@code progress}.
     */
    public static RenderResult render(ICamera camera, Supplier<Tracer> tracers, Function<Tracer, Shader> shaders,
            int width, int height, int threads, RenderProgress progress) {
        return render(camera, tracers, shaders, width, height, 1, threads, progress);
    }

    /**
     * As above, with {@code samples × samples} rays per pixel (Part II, "Anti-aliasing"): ray (i, j) passes through
     * {@code (x + (i + ½)/samples, y + (j + ½)/samples)}, and the pixel is the mean of their colours, each clamped to
     * [0, 1] first. One sample is the ray through the corner.
     */
    public static RenderResult render(ICamera camera, Supplier<Tracer> tracers, Function<Tracer, Shader> shaders,
            int width, int height, int samples, int threads, RenderProgress progress) {
        int[] pixels = new int[width * height];
        AtomicInteger nextBand = new AtomicInteger();
        List<Square> squares = new ArrayList<>();
        int bands = (height + TILE - 1) / TILE;
        for (int i = 0; i < Math.max(1, Math.min(threads, bands)); i++) { // more threads than bands would idle
            Tracer tracer = tracers.get();
            squares.add(new Square(camera, tracer, shaders.apply(tracer), width, height, samples));
        }
        List<Runnable> workers = new ArrayList<>();
        for (Square square : squares) {
            workers.add(() -> renderBands(square, pixels, bands, nextBand, progress));
        }
        runAll(workers);
        WorkCount work = WorkCount.NONE;
        for (Square square : squares) {
            work = work.plus(square.tracer.work()).plusSecondary(square.shader.secondaryRays());
        }
        return new RenderResult(new Picture(width, height, pixels), work);
    }

    private static void renderBands(Square square, int[] pixels, int bands, AtomicInteger nextBand,
            RenderProgress progress) {
        for (int taken = nextBand.getAndIncrement(); taken < bands; taken = nextBand.getAndIncrement()) {
            if (Thread.currentThread().isInterrupted()) {
                return; // another thread failed, and the picture will not be used
            }
            int top = bandTaken(taken, bands) * TILE;
            int bottom = Math.min(square.height, top + TILE);
            for (int left = 0; left < square.width; left += RUN * TILE) {
                square.renderRun(left, Math.min(square.width, left + RUN * TILE), top, bottom, pixels);
            }
            progress.rowsDone(bottom - top);
        }
    }

    /**
     * The band taken {@code taken}-th of {@code bands}: {@code taken · step mod bands}, each band once, as the step is
     * coprime to their number. Not from the top down, for the JIT's sake: it compiles the hot methods for what the
     * first few thousand rays did, and after a top band of sky, the floor's mirror rays further down would make it
     * compile them again. Scattered, the first bands show it the whole picture.
     */
    static int bandTaken(int taken, int bands) {
        return (int) ((long) taken * scatteringStep(bands) % bands);
    }

    /**
     * The whole number nearest to the golden section of {@code bands}, or the next above it coprime to {@code bands};
     * 52 of 135 bands (1080 rows), so they come 0, 52, 104, 21, 73, 125, ...
     */
    static int scatteringStep(int bands) {
        int step = Math.max(1, (int) Math.round(bands * GOLDEN_SECTION));
        while (gcd(step, bands) != 1) {
            step++;
        }
        return step;
    }

    private static int gcd(int a, int b) {
        return b == 0 ? a : gcd(b, a % b);
    }

    /** One thread's means to render squares of pixels and runs of them: its tracer, its shader, and their buffers. */
    private record Square(ICamera camera, Tracer tracer, Shader shader, int width, int height, int samples,
            RayBundle rays, HitBuffer hits, int[] rgb, float[] sum) {

        Square(ICamera camera, Tracer tracer, Shader shader, int width, int height, int samples) {
            this(camera, tracer, shader, width, height, samples, new RayBundle(RUN * TILE * TILE),
                    new HitBuffer(RUN * TILE * TILE), new int[RUN * TILE * TILE], new float[3 * TILE * TILE]);
        }

        /**
         * The pixels {@code [left, right) × [top, bottom)} of a band: all at once if the tracer can tell that none of
         * their rays hits anything (much of the paper's picture is sky), else each half so, down to the squares.
         */
        void renderRun(int left, int right, int top, int bottom, int[] pixels) {
            if (right - left <= TILE || samples > 1) {
                for (int x = left; x < right; x += TILE) {
                    int end = Math.min(right, x + TILE);
                    copy(render(x, top, end, bottom), x, top, end, bottom, pixels);
                }
                return;
            }
            rays.fill(camera, left, top, right, bottom, width, height);
            if (tracer.traceAtOnce(rays, hits)) {
                shader.rgbAll(rays, hits, rays.count(), rgb);
                copy(rgb, left, top, right, bottom, pixels);
                return;
            }
            int squares = (right - left + TILE - 1) / TILE;
            int middle = left + squares / 2 * TILE; // halves of whole squares: the same squares as one by one
            renderRun(left, middle, top, bottom, pixels);
            renderRun(middle, right, top, bottom, pixels);
        }

        /** The colours of {@code [left, right) × [top, bottom)}, row by row in {@code rgb}, into the picture. */
        private void copy(int[] rgb, int left, int top, int right, int bottom, int[] pixels) {
            for (int y = top; y < bottom; y++) {
                System.arraycopy(rgb, (y - top) * (right - left), pixels, y * width + left, right - left);
            }
        }

        /** The colours of the pixels {@code [left, right) × [top, bottom)} of a square, row by row. */
        private int[] render(int left, int top, int right, int bottom) {
            if (samples == 1) {
                rays.fill(camera, left, top, right, bottom, width, height);
                tracer.traceAll(rays, hits);
                shader.rgbAll(rays, hits, rays.count(), rgb);
                return rgb;
            }
            Arrays.fill(sum, 0);
            for (int j = 0; j < samples; j++) {
                for (int i = 0; i < samples; i++) {
                    rays.fill(camera, left, top, right, bottom, width, height, (i + 0.5f) / samples,
                            (j + 0.5f) / samples);
                    tracer.traceAll(rays, hits);
                    for (int k = 0; k < rays.count(); k++) {
                        Rgb clamped = shader.colour(rays, hits, k).clamped();
                        sum[3 * k] += clamped.red();
                        sum[3 * k + 1] += clamped.green();
                        sum[3 * k + 2] += clamped.blue();
                    }
                }
            }
            float n = samples * samples;
            for (int k = 0; k < rays.count(); k++) {
                rgb[k] = new Rgb(sum[3 * k] / n, sum[3 * k + 1] / n, sum[3 * k + 2] / n).toColor().getRGB();
            }
            return rgb;
        }
    }

    /** Runs the workers, the first on the calling thread, and rethrows what any threw. */
    private static void runAll(List<Runnable> workers) {
        // a thread is made at a worker's submission only: none for a single worker
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, workers.size() - 1), runnable -> {
            Thread thread = new Thread(runnable, "rtd-render");
            thread.setDaemon(true);
            return thread;
        });
        try {
            List<Future<?>> futures = new ArrayList<>();
            for (Runnable worker : workers.subList(1, workers.size())) {
                futures.add(pool.submit(worker));
            }
            workers.get(0).run();
            for (Future<?> future : futures) {
                future.get();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("rendering was interrupted", e);
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException runtime) {
                throw runtime;
            }
            if (cause instanceof Error error) {
                throw error;
            }
            throw new IllegalStateException(cause);
        } finally {
            pool.shutdownNow();
        }
    }
}
