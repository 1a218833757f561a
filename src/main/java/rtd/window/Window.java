package rtd.window;

import java.awt.AWTError;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import java.awt.event.ActionEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.AbstractAction;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSlider;
import javax.swing.JTextArea;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import rtd.image.Picture;
import rtd.io.SceneException;
import rtd.scene.Scene;
import rtd.view.View;
import rtd.window.WindowSetup.ClockedScene;

/**
 * {@code --window}: opens a window on a scene, thin Swing around its {@link WindowSession}, and waits until it is
 * closed: the picture ({@link PicturePanel}) beside the panel of text, under it the status line, above it the
 * clock slider of a scene that uses {@code clock}; the keys of {@link SidePanel#HELP}, {@code P}'s timer among them.
 * Its Swing parts are made and used on Swing's thread only.
 */
public final class Window implements Display {

    /** The panel of text's width in screen pixels. */
    private static final int SIDE_WIDTH = 460;
    private static final int SLIDER_STEPS = 1000;
    /** How often the window asks for the next frame while playing: 25 times a second at most. */
    private static final int TICK_MILLIS = 40;
    private static final Font TEXT = new Font(Font.MONOSPACED, Font.PLAIN, 12);

    private final JFrame frame;
    private final WindowSession session;
    private final PicturePanel picture;
    private final JTextArea panel = new JTextArea();
    private final JLabel status = new JLabel(" ");
    /** The clock slider, 0 to 1 in thousandths, with its label; shown for a scene that uses {@code clock}. */
    private final JSlider slider = new JSlider(0, SLIDER_STEPS, 0);
    private final JLabel clockLabel = new JLabel();
    private final JPanel clockBar = new JPanel(new BorderLayout(8, 0));
    /** Whether the slider is being set by the session, not by the user. */
    private boolean settingSlider;
    private final Timer play = new Timer(TICK_MILLIS, e -> tick());
    private long lastTick;

    /** Thrown where there is no screen to open a window on: a server, SSH without X, CI. */
    public static final class NoDisplay extends Exception {
        private static final long serialVersionUID = 1L;

        NoDisplay(String why) {
            super(why);
        }
    }

    /** Why no window can open here, in a few words ("DISPLAY is not set"), or null if one can. */
    public static String missingDisplay() {
        String display = System.getenv("DISPLAY");
        if (GraphicsEnvironment.isHeadless()) {
            return display == null || display.isBlank() ? "DISPLAY is not set" : "Java runs headless";
        }
        try {
            return GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices().length > 0 ? null
                    : "the display has no screen";
        } catch (AWTError | HeadlessException | InternalError | NoClassDefFoundError e) {
            // NoClassDefFoundError: asked again in a JVM whose first try to reach the display failed
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
        AtomicReference<Window> window = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> window.set(new Window(setup, source, scene, closed)));
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause instanceof HeadlessException || cause instanceof AWTError) {
                throw new NoDisplay(cause.getMessage());
            }
            throw cause instanceof RuntimeException runtime ? runtime : new IllegalStateException(cause);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        AutoCloseable watching = setup.watch().start(() -> reload(setup, window.get().session));
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

    /**
     * The scene file was saved: read it (and its meshes) on the watcher's thread, and hand it to the window's, which
     * parses it at the clock it shows; a file that cannot be read is a mistake, and the last good picture stays.
     */
    private static void reload(WindowSetup setup, WindowSession session) {
        ClockedScene source;
        try {
            source = setup.loader().read();
        } catch (IOException e) {
            SwingUtilities.invokeLater(() -> session.mistake("rtd: " + e.getMessage() + "\n", ""));
            return;
        }
        try {
            source.at(setup.clock()); // its meshes are read here, off the window's thread, and kept for every clock
        } catch (SceneException e) {
            // the window parses the file again at its own clock and shows the mistakes it finds there
        }
        SwingUtilities.invokeLater(() -> session.reloaded(source));
    }

    private Window(WindowSetup setup, ClockedScene source, Scene scene, CountDownLatch closed) {
        frame = new JFrame("rtd: " + setup.scene());
        session = new WindowSession(setup, source, scene, this, SwingUtilities::invokeLater);
        Dimension shown = fitted(setup.width(), setup.height());
        picture = new PicturePanel(session, shown.width, shown.height);
        panel.setEditable(false);
        panel.setFont(TEXT);
        panel.setLineWrap(true);
        panel.setWrapStyleWord(true);
        JScrollPane side = new JScrollPane(panel);
        side.setPreferredSize(new Dimension(SIDE_WIDTH, shown.height));
        status.setFont(TEXT);
        JPanel right = new JPanel(new BorderLayout());
        right.add(clockBar(), BorderLayout.NORTH);
        right.add(side, BorderLayout.CENTER);
        frame.add(picture, BorderLayout.CENTER);
        frame.add(right, BorderLayout.EAST);
        frame.add(status, BorderLayout.SOUTH);
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                play.stop();
                session.close();
                closed.countDown();
            }
        });
        bindKeys();
        frame.pack();
        frame.setLocationByPlatform(true);
        frame.setVisible(true);
        picture.requestFocusInWindow();
        session.start();
    }

    /**
     * The clock's label and slider, hidden until the session shows them: dragging renders at the moving resolution,
     * releasing (or a click on the track) the full picture.
     */
    private JPanel clockBar() {
        clockLabel.setFont(TEXT);
        slider.setFocusable(false); // the keys stay the window's
        slider.addChangeListener(e -> {
            if (!settingSlider) {
                session.slid((double) slider.getValue() / SLIDER_STEPS, slider.getValueIsAdjusting());
            }
        });
        clockBar.add(clockLabel, BorderLayout.WEST);
        clockBar.add(slider, BorderLayout.CENTER);
        clockBar.setVisible(false);
        return clockBar;
    }

    /**
     * The picture's size on the screen: its own, or scaled down to fit the screen beside the side panel (nine tenths of
     * it, for the window's frame and status line); a click still selects a pixel of the picture.
     */
    private static Dimension fitted(int width, int height) {
        Rectangle screen = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        double room = Math.min(1, Math.min((screen.width * 0.9 - SIDE_WIDTH) / width, screen.height * 0.9 / height));
        double scale = room > 0 ? room : 1;
        return new Dimension(Math.max(1, (int) (width * scale)), Math.max(1, (int) (height * scale)));
    }

    private void bindKeys() {
        key("1", () -> session.show(null));
        for (View view : View.values()) {
            key(Integer.toString(view.ordinal() + 2), () -> session.show(view));
        }
        key("V", session::nextView);
        key("R", session::resetCamera);
        key("C", session::copyCamera);
        key("P", this::playOrPause);
        key("ESCAPE", session::deselect);
        key("Q", frame::dispose);
        key("ctrl S", session::save);
    }

    private void key(String key, Runnable action) {
        JComponent root = frame.getRootPane();
        root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW).put(KeyStroke.getKeyStroke(key), key);
        root.getActionMap().put(key, new AbstractAction() {
            @Override
            public void actionPerformed(ActionEvent e) {
                action.run();
            }
        });
    }

    /** {@code P}: the session plays or pauses, and the timer runs while it plays. */
    private void playOrPause() {
        session.play();
        lastTick = System.nanoTime();
        if (session.playing()) {
            play.start();
        } else {
            play.stop();
        }
    }

    private void tick() {
        long now = System.nanoTime();
        session.tick(now - lastTick);
        lastTick = now;
        if (!session.playing()) {
            play.stop(); // a saved scene without the clock stops it
        }
    }

    @Override
    public void picture(Picture shown) {
        picture.picture(shown);
    }

    @Override
    public void rays(List<RayTreeProjection.Line> lines) {
        picture.rays(lines);
    }

    @Override
    public void panel(String text) {
        panel.setText(text);
        panel.setCaretPosition(0);
    }

    @Override
    public void status(String text) {
        status.setText(text);
    }

    @Override
    public void clock(Double clock) {
        if (clock != null) {
            clockLabel.setText(WindowSession.label(clock));
            settingSlider = true;
            slider.setValue((int) Math.round(Math.max(0, Math.min(1, clock)) * SLIDER_STEPS));
            settingSlider = false;
        }
        clockBar.setVisible(clock != null);
    }

    @Override
    public void copy(String text) {
        try {
            Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(text), null);
        } catch (IllegalStateException e) {
            // the clipboard is busy: the panel shows the line to copy by hand
        }
    }
}
