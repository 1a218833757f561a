package rtd.render;

import java.util.concurrent.atomic.AtomicInteger;

/**
 * How many image rows are finished: {@link ParallelRenderer} counts them up while another
 * thread (the command line's progress display) reads them.
 */
public final class RenderProgress {

    private final AtomicInteger rowsDone = new AtomicInteger();

    void rowsDone(int rows) {
        rowsDone.addAndGet(rows);
    }

    /** The number of finished rows. */
    public int rowsDone() {
        return rowsDone.get();
    }
}
