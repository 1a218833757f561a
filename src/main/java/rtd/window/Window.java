package rtd.window;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import rtd.io.SceneException;
import rtd.scene.Scene;
import rtd.window.WindowSetup.ClockedScene;

/**
 * {@code --window}: opens a window on a scene and waits until it is closed. The picture renders coarse at once and is
 * refined on all cores; the mouse orbits, pans and zooms the camera; a click explains a pixel as {@code --explain}
 * does, with its rays drawn over the picture; keys switch to the debug views of {@code --view}; saving the scene file
 * renders it again, as {@code --watch}; a scene that uses {@code clock} has a clock slider and a play key.
 */
public final class Window {

    private Window() {
    }

    /** Thrown where there is no screen to open a window on: a server, SSH without X, CI. */
    public static final class NoDisplay extends Exception {
        private static final long serialVersionUID = 1L;

        NoDisplay(String why) {
            super(why);
        }
    }

    /**
     * Why no window can open here, in a few words ("DISPLAY is not set"), or null if one can: Java runs headless
     * without a display, and a display that cannot be reached fails when the first window would open. Where one cannot,
     * {@link #open} throws {@link NoDisplay}.
     */
    public static String missingDisplay() {
        String display = System.getenv("DISPLAY");
        if (GraphicsEnvironment.isHeadless()) {
            return display == null || display.isBlank() ? "DISPLAY is not set" : "Java runs headless";
        }
        try {
            return GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices().length > 0 ? null
                    : "the display has no screen";
        } catch (AWTError | HeadlessException | InternalError e) {
            return "the display '" + display + "' that DISPLAY names cannot be reached";
        }
    }

    /**
     * Reads the scene, opens its window and returns once it is closed. A scene with mistakes opens no window: they are
     * thrown, as for {@code -o}.
     */
    public static void open(WindowSetup setup) throws SceneException, IOException, NoDisplay {
        String missing = missingDisplay();
        if (missing != null) {
            throw new NoDisplay(missing);
        }
        ClockedScene source = setup.loader().read();
        Scene scene = source.at(setup.clock());
        CountDownLatch closed = new CountDownLatch(1);
        AtomicReference<SceneWindow> window = new AtomicReference<>();
        show(() -> {
            SceneWindow opened = new SceneWindow(setup, source, scene, closed);
            window.set(opened);
            opened.open();
        });
        AutoCloseable watching = setup.watch().start(() -> reload(setup, window.get()));
        try {
            closed.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            try {
                watching.close();
            } catch (Exception e) {
                // the watcher could not stop cleanly: its thread is a daemon, and the window is closed
            }
        }
    }

    /** Opens the window on Swing's thread; no display there is {@link NoDisplay}. */
    private static void show(Runnable open) throws NoDisplay {
        try {
            SwingUtilities.invokeAndWait(open);
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause instanceof HeadlessException || cause instanceof AWTError) {
                throw new NoDisplay(cause.getMessage());
            }
            if (cause instanceof RuntimeException runtime) {
                throw runtime;
            }
            throw new IllegalStateException(cause);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * The scene file was saved: read it (and its meshes) on the watcher's thread, and hand it to the window's, which
     * parses it at the clock it shows; a file that cannot be read is a mistake, and the last good picture stays.
     */
    private static void reload(WindowSetup setup, SceneWindow window) {
        ClockedScene source;
        try {
            source = setup.loader().read();
        } catch (IOException e) {
            SwingUtilities.invokeLater(() -> window.session().mistake("rtd: " + e.getMessage() + "\n", ""));
            return;
        }
        try {
            source.at(setup.clock()); // its meshes are read here, off the window's thread, and kept for every clock
        } catch (SceneException e) {
            // the window parses the file again at its own clock and shows the mistakes it finds there
        }
        SwingUtilities.invokeLater(() -> window.session().reloaded(source));
    }
}
