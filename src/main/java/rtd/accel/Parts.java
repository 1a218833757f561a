package rtd.accel;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.Future;
import java.util.function.Function;

/**
 * The places {@code [0, count)} cut into a part per thread of a pool, {@value #MOST} at most, for
 * passes whose parts run in parallel ({@link ViewGridBuilder}); one part, on the calling thread,
 * without a pool.
 */
final class Parts {

    /** A pass over the places {@code [start, end)}, the part numbered {@code part}. */
    interface Pass {
        void run(int start, int end, int part);
    }

    /** The most parts: a part of the view grid's passes keeps a count for every cell of the image. */
    static final int MOST = 8;
    /** The fewest objects for which the grids are built on a pool: for fewer, starting threads takes longer. */
    static final int PARALLEL_THRESHOLD = 20_000;

    final int count;
    final int parts;
    private final ForkJoinPool pool;

    Parts(int count, ForkJoinPool pool) {
        this.count = count;
        this.pool = pool;
        this.parts = pool == null ? 1 : Math.min(MOST, pool.getParallelism());
    }

    /**
     * What {@code build} makes on a pool of {@code threads} threads, shut down afterwards, or on
     * this thread (a null pool) for one thread or fewer than {@link #PARALLEL_THRESHOLD} objects.
     */
    static <T> T onPool(int threads, int objects, Function<ForkJoinPool, T> build) {
        ForkJoinPool pool = threads > 1 && objects >= PARALLEL_THRESHOLD ? new ForkJoinPool(threads) : null;
        try {
            return build.apply(pool);
        } finally {
            if (pool != null) {
                pool.shutdown();
            }
        }
    }

    /** Runs {@code pass} on every part, in parallel if there is a pool, and returns when all are done. */
    void run(Pass pass) {
        if (pool == null) {
            pass.run(0, count, 0);
            return;
        }
        List<Callable<Void>> tasks = new ArrayList<>();
        for (int p = 0; p < parts; p++) {
            int part = p;
            tasks.add(() -> {
                pass.run(start(part), start(part + 1), part);
                return null;
            });
        }
        for (Future<Void> done : pool.invokeAll(tasks)) {
            join(done);
        }
    }

    /** The result of a task on the pool, once it is done; what it threw, thrown again. */
    static <T> T join(Future<T> task) {
        try {
            return task.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("building was interrupted", e);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw e.getCause() instanceof RuntimeException failure ? failure : new IllegalStateException(e.getCause());
        }
    }

    /**
     * Turns counts per part and per cell (of the view grid) into where each part's
     * share of each cell starts: a cell's share of the first part, then of the second, and so on,
     * cell after cell, so that a cell's objects come in file order however many parts there are.
     * The cells' starts go into {@code starts} (one longer than the cells), and the answer is the
     * sum of all.
     */
    static int runningSums(int[][] perPart, int[] starts) {
        int cells = starts.length - 1;
        int total = 0;
        for (int c = 0; c < cells; c++) {
            starts[c] = total;
            for (int[] counts : perPart) {
                int count = counts[c];
                counts[c] = total;
                total += count;
            }
        }
        starts[cells] = total;
        return total;
    }

    /** Where part {@code part} starts. */
    private int start(int part) {
        return (int) ((long) count * part / parts);
    }
}
