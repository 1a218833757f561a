package rtd.render;

import java.util.concurrent.atomic.AtomicInteger;

/** How many image rows are finished: {@link ParallelRenderer} counts them while the progress display reads them. */
public final class RenderProgress {

    private final AtomicInteger rowsDone = new AtomicInteger();

    void rowsDone(int rows) {
        rowsDone.addAndGet(rows);
    }

    public int rowsDone() {
        return rowsDone.get();
    }
}
