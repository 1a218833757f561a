package rtd.window;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import rtd.accel.Accelerator;
import rtd.cli.WindowRun;
import rtd.image.Picture;
import rtd.io.SceneFile;
import rtd.window.WindowSetup.ClockedScene;

/**
 * A {@link WindowSession} without a screen, for tests: its window's thread is a single thread of its own, as
 * Swing's would be, and what it shows is recorded ({@link Shown}), read on that thread only.
 */
final class SessionHarness implements AutoCloseable {

    final ExecutorService ui = Executors.newSingleThreadExecutor();
    final Shown display = new Shown();
    WindowSession session;

    /** A session on the scene file {@code file} at {@code width × height}, started at {@code clock}. */
    static SessionHarness open(Path file, int width, int height, double clock) throws Exception {
        SessionHarness harness = new SessionHarness();
        WindowSetup.SceneLoader loader = () -> new ClockedScene(SceneFile.read(file), scene -> scene);
        WindowSetup setup = new WindowSetup(file, loader, changed -> () -> { },
                WindowRun.engine(Accelerator.Choice.auto, 2), width, height, 1, 2, clock);
        ClockedScene source = loader.read();
        harness.on(() -> {
            harness.session = new WindowSession(setup, source, source.at(clock), harness.display, harness.ui);
            harness.session.start();
            return null;
        });
        return harness;
    }

    /** Runs {@code action} on the window's thread. */
    void run(Runnable action) throws Exception {
        on(() -> {
            action.run();
            return null;
        });
    }

    /** Asks {@code question} on the window's thread. */
    <T> T on(Callable<T> question) throws Exception {
        return ui.submit(question).get(30, TimeUnit.SECONDS);
    }

    /** Waits until {@code question}, asked on the window's thread, is true, at most 30 s. */
    void awaitTrue(Callable<Boolean> question) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (System.nanoTime() < end) {
            if (on(question)) {
                return;
            }
            Thread.sleep(20);
        }
        throw new AssertionError("not within 30 s");
    }

    /** The full picture, once one is shown. */
    Picture awaitFull() throws Exception {
        awaitTrue(() -> session.shown() != null && session.shown().block() == 1);
        return on(() -> session.shown().picture());
    }

    @Override
    public void close() {
        ui.submit(() -> session.close());
        ui.shutdown();
    }

    /** What the window would show. */
    static final class Shown implements Display {
        String panel = "";
        String status = "";
        String copied;
        /** The slider's value, null for hidden; NaN before the session said. */
        Double clock = Double.NaN;
        List<RayTreeProjection.Line> rays = List.of();

        @Override
        public void picture(Picture picture) {
        }

        @Override
        public void rays(List<RayTreeProjection.Line> lines) {
            rays = lines;
        }

        @Override
        public void panel(String text) {
            panel = text;
        }

        @Override
        public void status(String text) {
            status = text;
        }

        @Override
        public void clock(Double shown) {
            clock = shown;
        }

        @Override
        public void copy(String text) {
            copied = text;
        }
    }
}
