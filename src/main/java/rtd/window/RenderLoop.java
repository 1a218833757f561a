package rtd.window;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.FutureTask;
import java.util.function.Consumer;

/**
 * The window's render thread: it runs one job at a time, the newest asked for; a job still waiting is dropped for a
 * newer one. A job that cancels interrupts the one in progress ({@link FrameRenderer} stops at its next band of rows),
 * so the picture always follows the latest camera, and the window's own thread (Swing's) never waits for a render.
 */
final class RenderLoop implements AutoCloseable {

    private final ExecutorService thread = Executors.newSingleThreadExecutor(job -> daemon(job, "rtd-window-render"));
    private final Consumer<RuntimeException> failed;
    /** Counts the jobs asked for: one that is not the newest when its turn comes is dropped. */
    private long asked;
    private Future<?> running = new FutureTask<>(() -> null);

    /** A loop whose jobs' failures (bugs, not cancels) go to {@code failed}, on the render thread. */
    RenderLoop(Consumer<RuntimeException> failed) {
        this.failed = failed;
    }

    /**
     * Runs {@code job} next, in place of any job still waiting; {@code cancel} whether it cancels the one running (a
     * still picture does; a moving frame waits for the one before, so that frames are finished and shown).
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
                    failed.accept(e); // a bug; the loop goes on with the next job
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
    }

    /** Stops the thread: the job in progress is cancelled, and no other runs. */
    @Override
    public synchronized void close() {
        asked++;
        running.cancel(true);
        thread.shutdownNow();
    }

    /** A daemon thread named {@code name} that runs {@code job}: the window's threads never keep Java running. */
    static Thread daemon(Runnable job, String name) {
        Thread thread = new Thread(job, name);
        thread.setDaemon(true);
        return thread;
    }
}
