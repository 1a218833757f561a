package rtd.window;

import java.util.function.Consumer;

/**
 * The window's render thread: it runs one job at a time, the newest asked for. Asking for a new job cancels the one in
 * progress (it interrupts the thread, and {@link FrameRenderer} stops at its next band of rows), so the picture always
 * follows the latest camera, and the window's own thread (Swing's) never waits for a render.
 */
final class RenderLoop implements AutoCloseable {

    private final Thread thread;
    private final Consumer<RuntimeException> failed;
    private Runnable pending;
    private boolean running;
    private boolean closed;

    /** A loop whose jobs' failures (bugs, not cancels) go to {@code failed}, on the render thread. */
    RenderLoop(Consumer<RuntimeException> failed) {
        this.failed = failed;
        thread = new Thread(this::work, "rtd-window-render");
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * Runs {@code job} next, in place of any job still waiting; {@code cancel} whether it cancels the one running (a
     * still picture does; a moving frame waits for the one before, so that frames are finished and shown).
     */
    synchronized void submit(Runnable job, boolean cancel) {
        pending = job;
        if (running && cancel) {
            thread.interrupt();
        }
        notifyAll();
    }

    /** Stops the thread: the job in progress is cancelled, and no other runs. */
    @Override
    public synchronized void close() {
        closed = true;
        pending = null;
        thread.interrupt();
        notifyAll();
    }

    private void work() {
        while (true) {
            Runnable job;
            synchronized (this) {
                while (pending == null && !closed) {
                    try {
                        wait();
                    } catch (InterruptedException e) {
                        // close() wakes us: the loop's condition decides
                    }
                }
                if (closed) {
                    return;
                }
                job = pending;
                pending = null;
                running = true;
                Thread.interrupted(); // a cancel meant for the job before
            }
            try {
                job.run();
            } catch (RuntimeException e) {
                if (!Thread.currentThread().isInterrupted()) {
                    failed.accept(e); // a bug; the loop goes on with the next job
                }
            } finally {
                synchronized (this) {
                    running = false;
                }
                Thread.interrupted();
            }
        }
    }
}
