package rtd.window;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.List;
import java.util.concurrent.CountDownLatch;
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
import rtd.scene.Scene;
import rtd.view.View;
import rtd.window.WindowSetup.ClockedScene;

/**
 * The window itself, thin Swing around a {@link WindowSession}: the picture on the left, the panel of text on the right
 * (the explanation, the copied camera, a scene's mistakes) under the clock slider of a scene that uses {@code clock},
 * the status line below, and the keys ({@link #HELP}), {@code P}'s timer among them. Made and used on Swing's thread
 * only.
 */
final class SceneWindow implements Display {

    /** The window's keys and mouse, as its panel shows them before a pixel is selected (and the README's table). */
    static final String HELP = String.join("\n",
            "rtd's window: click a pixel to see what rtd does for it.",
            "",
            "  drag        orbit around what the centre pixel sees",
            "  right drag  pan (or Shift + drag)",
            "  wheel       zoom",
            "  click       explain the pixel, its rays over the picture",
            "  1 to 5      picture, cost, depth, normal, id (V: next)",
            "  R           the file's camera again",
            "  C           copy the camera as a scene line",
            "  P           play the clock, 0 to 1 in 5 s, or pause",
            "  Ctrl+S      save the picture as NAME-window.png",
            "  Esc         no pixel selected",
            "  Q           quit",
            "",
            "Saving the scene file renders it again. A scene that uses clock",
            "has a clock slider above this panel.",
            "");

    /** The side panel's width in screen pixels. */
    private static final int SIDE_WIDTH = 460;
    private static final int SLIDER_STEPS = 1000;
    private static final Font TEXT = new Font(Font.MONOSPACED, Font.PLAIN, 12);

    private final JFrame frame;
    private final WindowSession session;
    private final PicturePanel picture;
    private final JTextArea panel = new JTextArea();
    private final JLabel status = new JLabel(" ");
    /** The clock slider: 0 to 1 in thousandths, with its label; shown for a scene that uses {@code clock}. */
    private final JSlider slider = new JSlider(0, SLIDER_STEPS, 0);
    private final JLabel clockLabel = new JLabel();
    private final JPanel clockBar = new JPanel(new BorderLayout(8, 0));
    /** Whether the slider is being set by the session, not by the user. */
    private boolean settingSlider;
    private final Timer play = new Timer(ClockControl.TICK_MILLIS, e -> tick());
    private long lastTick;
    private final CountDownLatch closed;

    SceneWindow(WindowSetup setup, ClockedScene source, Scene scene, CountDownLatch closed) {
        this.closed = closed;
        this.frame = new JFrame("rtd: " + setup.scene());
        this.session = new WindowSession(setup, source, scene, this, SwingUtilities::invokeLater);
        Dimension shown = fitted(setup.width(), setup.height());
        this.picture = new PicturePanel(session, shown.width, shown.height);
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
        frame.getContentPane().add(picture, BorderLayout.CENTER);
        frame.getContentPane().add(right, BorderLayout.EAST);
        frame.getContentPane().add(status, BorderLayout.SOUTH);
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
                session.clock().slid((double) slider.getValue() / SLIDER_STEPS, slider.getValueIsAdjusting());
            }
        });
        clockBar.add(clockLabel, BorderLayout.WEST);
        clockBar.add(slider, BorderLayout.CENTER);
        clockBar.setVisible(false);
        return clockBar;
    }

    /** {@code P}: the session plays or pauses, and the timer runs while it plays. */
    private void playOrPause() {
        session.clock().play();
        if (session.clock().playing()) {
            lastTick = System.nanoTime();
            play.start();
        } else {
            play.stop();
        }
    }

    private void tick() {
        long now = System.nanoTime();
        session.clock().tick(now - lastTick);
        lastTick = now;
        if (!session.clock().playing()) {
            play.stop(); // a saved scene without the clock stops it
        }
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

    void open() {
        frame.setVisible(true);
        picture.requestFocusInWindow();
        session.start();
    }

    WindowSession session() {
        return session;
    }

    private void bindKeys() {
        key("1", () -> session.show(null));
        View[] views = View.values();
        for (int i = 0; i < views.length; i++) {
            View view = views[i];
            key(Integer.toString(i + 2), () -> session.show(view));
        }
        key("V", session::nextView);
        key("R", session::resetCamera);
        key("C", session::copyCamera);
        key("P", this::playOrPause);
        key("ESCAPE", session::deselect);
        key("Q", frame::dispose);
        bind(KeyStroke.getKeyStroke(KeyEvent.VK_S, InputEvent.CTRL_DOWN_MASK), "save", session::save);
    }

    private void key(String key, Runnable action) {
        bind(KeyStroke.getKeyStroke(key), key, action);
    }

    private void bind(KeyStroke stroke, String name, Runnable action) {
        JComponent root = frame.getRootPane();
        root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW).put(stroke, name);
        root.getActionMap().put(name, new AbstractAction() {
            @Override
            public void actionPerformed(ActionEvent e) {
                action.run();
            }
        });
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
        if (clock == null) {
            clockBar.setVisible(false);
            return;
        }
        clockLabel.setText(ClockControl.label(clock));
        settingSlider = true;
        slider.setValue((int) Math.round(Math.max(0, Math.min(1, clock)) * SLIDER_STEPS));
        settingSlider = false;
        clockBar.setVisible(true);
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
