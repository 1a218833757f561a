package rtd.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import rtd.camera.ICamera;
import rtd.math.Ray;

/**
 * Listing 4.2 on all cores: the same ray per pixel as {@link rtd.scene.Scene#render}, with
 * the rows shared out among threads.
 *
 * <p>Every pixel depends only on its own ray, so the picture is the same for any number of
 * threads: the threads only change which pixel is done when. A thread takes the next row
 * not yet taken, so a slow row does not hold the others back.
 */
public final class ParallelRenderer {

    private ParallelRenderer() {
    }

    /**
     * Renders a {@code width × height} image with {@code threads} threads, each with its own
     * tracer from {@code tracers}, and counts finished rows in {@code progress}.
     */
    public static RenderResult render(ICamera camera, Supplier<Tracer> tracers, int width, int height,
            int threads, RenderProgress progress) {
        int[] pixels = new int[width * height];
        AtomicInteger nextRow = new AtomicInteger();
        List<Tracer> used = new ArrayList<>();
        List<Runnable> workers = new ArrayList<>();
        for (int i = 0; i < Math.min(threads, height); i++) { // more threads than rows would idle
            Tracer tracer = tracers.get();
            used.add(tracer);
            workers.add(() -> renderRows(camera, tracer, width, height, pixels, nextRow, progress));
        }
        runAll(workers);
        WorkCount work = WorkCount.NONE;
        for (Tracer tracer : used) {
            work = work.plus(tracer.work());
        }
        return new RenderResult(new Picture(width, height, pixels), work);
    }

    private static void renderRows(ICamera camera, Tracer tracer, int width, int height, int[] pixels,
            AtomicInteger nextRow, RenderProgress progress) {
        for (int y = nextRow.getAndIncrement(); y < height; y = nextRow.getAndIncrement()) {
            int rowStart = y * width;
            for (int x = 0; x < width; x++) {
                Ray ray = camera.generateRay(x, y, width, height);
                pixels[rowStart + x] = tracer.trace(ray).getRGB();
            }
            progress.rowDone();
        }
    }

    /** Runs the workers, the last one on the calling thread, and rethrows what any threw. */
    private static void runAll(List<Runnable> workers) {
        if (workers.size() == 1) {
            workers.get(0).run();
            return;
        }
        ExecutorService pool = Executors.newFixedThreadPool(workers.size() - 1, runnable -> {
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
