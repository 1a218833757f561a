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
 * <p>The result does not depend on the number of threads. The chunks depend only on the node's
 * range; their bins are added up in chunk order; and the partition is stable: each chunk
 * copies its objects to the left or right part of a second set of arrays at places counted in
 * advance from the chunks' bins, keeping their order, and the node's range is copied back.
 */
final class ChunkedPasses {

    /** The number of objects in a chunk. */
    static final int CHUNK = 1 << 14;

    private final int[] order;
    private final float[] boxes;
    /** The second set of arrays that the partition copies into, as large as the first. */
    private final int[] orderCopy;
    private final float[] boxesCopy;
    /** The threads, or {@code null} to run the chunks one after another on this thread. */
    private final ForkJoinPool pool;

    ChunkedPasses(int[] order, float[] boxes, int count, ForkJoinPool pool) {
        this.order = order;
        this.boxes = boxes;
        this.orderCopy = new int[count];
        this.boxesCopy = new float[6 * count];
        this.pool = pool;
    }

    /** The extent of the objects in {@code order[start, end)}. */
    Extent measure(int start, int end) {
        Extent[] parts = new Extent[chunks(start, end)];
        run(parts.length, c -> {
            Extent part = Extent.empty();
            for (int i = first(start, c); i < last(start, end, c); i++) {
                part.add(boxes, 6 * i);
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
     * Bins the objects of {@code order[start, end)} along {@code axis} into {@code into} (which
     * starts empty), and answers each chunk's bins, which {@link #partition} needs.
     */
    SahBins[] bin(int start, int end, int axis, float lo, float scale, SahBins into) {
        SahBins[] parts = new SahBins[chunks(start, end)];
        run(parts.length, c -> {
            SahBins part = new SahBins();
            part.add(boxes, first(start, c), last(start, end, c), axis, lo, scale);
            parts[c] = part;
        });
        for (SahBins part : parts) {
            into.add(part);
        }
        return parts;
    }

    /**
     * Moves the objects of {@code order[start, end)} in bins {@code ≤ lastLeftBin} to the front,
     * keeping the order on each side; {@code parts} are the chunks' bins from {@link #bin}.
     * Answers where the right side starts.
     */
    int partition(int start, int end, int axis, float lo, float scale, int lastLeftBin, SahBins[] parts,
            Extent left, Extent right) {
        int[] lefts = new int[parts.length];
        int[] rights = new int[parts.length];
        int middle = start;
        for (int c = 0; c < parts.length; c++) {
            lefts[c] = middle;
            middle += parts[c].count(lastLeftBin + 1);
        }
        int place = middle;
        for (int c = 0; c < parts.length; c++) {
            rights[c] = place;
            place += (last(start, end, c) - first(start, c)) - parts[c].count(lastLeftBin + 1);
        }
        CentreBox[] leftCentres = new CentreBox[parts.length];
        CentreBox[] rightCentres = new CentreBox[parts.length];
        run(parts.length, c -> {
            leftCentres[c] = new CentreBox();
            rightCentres[c] = new CentreBox();
            scatter(first(start, c), last(start, end, c), axis, lo, scale, lastLeftBin, lefts[c], rights[c],
                    leftCentres[c], rightCentres[c]);
        });
        run(parts.length, c -> copyBack(first(start, c), last(start, end, c)));
        for (int c = 0; c < parts.length; c++) {
            leftCentres[c].growInto(left.centres());
            rightCentres[c].growInto(right.centres());
        }
        return middle;
    }

    /**
     * Copies the objects of {@code [from, to)} to the copies, those going left from {@code left}
     * on, the others from {@code right} on, and grows each side's box of centres by theirs.
     */
    private void scatter(int from, int to, int axis, float lo, float scale, int lastLeftBin, int left, int right,
            CentreBox leftCentres, CentreBox rightCentres) {
        for (int i = from; i < to; i++) {
            int at = 6 * i;
            boolean goesLeft = SahBins.binOf((boxes[at + axis] + boxes[at + axis + 3]) * 0.5f, lo, scale) <= lastLeftBin;
            (goesLeft ? leftCentres : rightCentres).add(boxes, at);
            int place = goesLeft ? left++ : right++;
            orderCopy[place] = order[i];
            int to6 = 6 * place;
            for (int k = 0; k < 6; k++) {
                boxesCopy[to6 + k] = boxes[at + k];
            }
        }
    }

    private void copyBack(int from, int to) {
        System.arraycopy(orderCopy, from, order, from, to - from);
        System.arraycopy(boxesCopy, 6 * from, boxes, 6 * from, 6 * (to - from));
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
