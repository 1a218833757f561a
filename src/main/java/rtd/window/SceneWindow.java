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
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import rtd.image.Picture;
import rtd.scene.Scene;
import rtd.view.View;

/**
 * The window itself, thin Swing around a {@link WindowSession}: the picture on the left, the panel of text on the
 * right (the explanation, the copied camera, a scene's mistakes), the status line below, and the keys
 * ({@link Keys}). Made and used on Swing's thread only.
 */
final class SceneWindow implements Display {

    /** The side panel's width in screen pixels. */
    private static final int SIDE_WIDTH = 460;

    private final JFrame frame;
    private final WindowSession session;
    private final PicturePanel picture;
    private final JTextArea panel = new JTextArea();
    private final JLabel status = new JLabel(" ");
    private final CountDownLatch closed;

    SceneWindow(WindowSetup setup, Scene scene, CountDownLatch closed) {
        this.closed = closed;
        this.frame = new JFrame("rtd: " + setup.scene());
        this.session = new WindowSession(setup, scene, this, SwingUtilities::invokeLater);
        Dimension shown = fitted(setup.width(), setup.height());
        this.picture = new PicturePanel(session, shown.width, shown.height);
        panel.setEditable(false);
        panel.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        panel.setLineWrap(true);
        panel.setWrapStyleWord(true);
        JScrollPane side = new JScrollPane(panel);
        side.setPreferredSize(new Dimension(SIDE_WIDTH, shown.height));
        status.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        frame.getContentPane().add(picture, BorderLayout.CENTER);
        frame.getContentPane().add(side, BorderLayout.EAST);
        frame.getContentPane().add(status, BorderLayout.SOUTH);
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                session.close();
                closed.countDown();
            }
        });
        bindKeys();
        frame.pack();
        frame.setLocationByPlatform(true);
    }

    /**
     * The picture's size on the screen: its own, or scaled down to fit the screen beside the side panel (nine
     * tenths of it, for the window's frame and status line); a click still selects a pixel of the picture.
     */
    private static Dimension fitted(int width, int height) {
        Rectangle screen = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        double room = Math.min(1, Math.min((screen.width * 0.9 - SIDE_WIDTH) / width, screen.height * 0.9 / height));
        double scale = room > 0 ? room : 1;
        return new Dimension(Math.max(1, (int) (width * scale)), Math.max(1, (int) (height * scale)));
    }

    /** Shows the window and starts the first render. */
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
    public void copy(String text) {
        try {
            Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(text), null);
        } catch (IllegalStateException e) {
            // the clipboard is busy: the panel shows the line to copy by hand
        }
    }
}
