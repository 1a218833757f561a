package rtd.accel;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveAction;
import java.util.function.IntConsumer;

/**
 * The passes of {@link BvhBuilder} over the objects of a large node (measuring, binning,
 * partitioning), cut into chunks of {@value #CHUNK} objects that the pool's threads share. The
 * top levels of the tree hold all objects in few nodes: without this, one thread would bin and
 * partition a million objects while the other cores wait.
 *
 * <p>The result does not depend on the number of threads, nor on the chunks: their bins are
 * added up in chunk order, and each chunk copies its objects to the places that the chunks
 * before it leave free on each side, counted in advance from their bins, so the partition
 * keeps the objects' order as {@link ObjectArrays#scatter} on the whole node would.
 */
final class ChunkedPasses {

    /** The number of objects in a chunk. */
    static final int CHUNK = 1 << 14;

    /** The threads, or {@code null} to run the chunks one after another on this thread. */
    private final ForkJoinPool pool;

    ChunkedPasses(ForkJoinPool pool) {
        this.pool = pool;
    }

    /** The extent of the objects in places {@code [start, end)} of {@code data}. */
    Extent measure(ObjectArrays data, int start, int end) {
        Extent[] parts = new Extent[chunks(start, end)];
        run(parts.length, c -> {
            Extent part = Extent.empty();
            for (int i = first(start, c); i < last(start, end, c); i++) {
                part.add(data.boxes(), 6 * i);
            }
            parts[c] = part;
        });
        Extent all = Extent.empty();
        for (Extent part : parts) {
            all.add(part);
        }
        return all;
    }

    /**
     * Bins the objects of places {@code [start, end)} of {@code data} along {@code axis} into
     * {@code into} (which starts empty), and answers each chunk's bins, which {@link #partition}
     * needs.
     */
    SahBins[] bin(ObjectArrays data, int start, int end, int axis, float lo, float scale, SahBins into) {
        SahBins[] parts = new SahBins[chunks(start, end)];
        run(parts.length, c -> {
            SahBins part = new SahBins();
            part.add(data.boxes(), first(start, c), last(start, end, c), axis, lo, scale);
            parts[c] = part;
        });
        for (SahBins part : parts) {
            into.add(part);
        }
        return parts;
    }

    /**
     * {@link ObjectArrays#scatter} of places {@code [start, end)} from {@code data} to
     * {@code to}, the left side from {@code start} on and the right side from {@code middle}
     * on; {@code parts} are the chunks' bins from {@link #bin}.
     */
    void partition(ObjectArrays data, int start, int end, int axis, float lo, float scale, int lastLeftBin,
            SahBins[] parts, ObjectArrays to, int middle) {
        int[] lefts = new int[parts.length];
        int[] rights = new int[parts.length];
        int left = start;
        int right = middle;
        for (int c = 0; c < parts.length; c++) {
            lefts[c] = left;
            rights[c] = right;
            int goingLeft = parts[c].count(lastLeftBin + 1);
            left += goingLeft;
            right += last(start, end, c) - first(start, c) - goingLeft;
        }
        run(parts.length, c -> data.scatter(first(start, c), last(start, end, c), axis, lo, scale, lastLeftBin, to,
                lefts[c], rights[c]));
    }

    private static int chunks(int start, int end) {
        return (end - start + CHUNK - 1) / CHUNK;
    }

    private static int first(int start, int chunk) {
        return start + chunk * CHUNK;
    }

    private static int last(int start, int end, int chunk) {
        return Math.min(end, first(start, chunk) + CHUNK);
    }

    /** Runs {@code work} for chunks 0 to {@code chunks − 1}: side by side on the pool, or in order. */
    private void run(int chunks, IntConsumer work) {
        if (pool == null) {
            for (int c = 0; c < chunks; c++) {
                work.accept(c);
            }
            return;
        }
        List<ChunkTask> tasks = new ArrayList<>(chunks);
        for (int c = 0; c < chunks; c++) {
            tasks.add(new ChunkTask(work, c));
        }
        ForkJoinTask.invokeAll(tasks);
    }

    /** One chunk's work, as a task another thread can take. */
    private static final class ChunkTask extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient IntConsumer work;
        private final int chunk;

        ChunkTask(IntConsumer work, int chunk) {
            this.work = work;
            this.chunk = chunk;
        }

        @Override
        protected void compute() {
            work.accept(chunk);
        }
    }
}
