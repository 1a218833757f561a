package rtd.window;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.InputEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.image.BufferedImage;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import rtd.explain.RayTree;
import rtd.image.Picture;
import rtd.math.Vector3f;

/**
 * The picture in the window, scaled to fit and centred ({@link PixelMapping}), with the selected pixel's rays over it;
 * the mouse's drags, wheel and clicks go to the {@link WindowSession}. Runs on Swing's thread only.
 */
final class PicturePanel extends JComponent {

    private static final long serialVersionUID = 1L;
    /** How long the mouse must rest before the full picture is rendered. */
    static final int REST_MILLIS = 150;
    private static final Color OUTLINE = new Color(0, 0, 0, 160);

    private final WindowSession session;
    private final Timer rest;
    private BufferedImage image;
    private List<RayTreeProjection.Line> rays = List.of();

    PicturePanel(WindowSession session, int width, int height) {
        this.session = session;
        this.rest = new Timer(REST_MILLIS, e -> session.rested());
        rest.setRepeats(false);
        setPreferredSize(new Dimension(width, height));
        setFocusable(true);
        MouseAdapter mouse = new Mouse();
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
    }

    void picture(Picture picture) {
        if (image == null || image.getWidth() != picture.width() || image.getHeight() != picture.height()) {
            image = new BufferedImage(picture.width(), picture.height(), BufferedImage.TYPE_INT_RGB);
        }
        image.setRGB(0, 0, picture.width(), picture.height(), picture.rgb(), 0, picture.width());
        repaint();
    }

    void rays(List<RayTreeProjection.Line> lines) {
        rays = lines;
        repaint();
    }

    WindowSession session() {
        return session;
    }

    PixelMapping mapping() {
        return image == null ? null : PixelMapping.of(image.getWidth(), image.getHeight(), getWidth(), getHeight());
    }

    List<RayTreeProjection.Line> rays() {
        return rays;
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        g.setColor(Color.DARK_GRAY);
        g.fillRect(0, 0, getWidth(), getHeight());
        PixelMapping map = mapping();
        if (map != null) {
            int left = (int) Math.round(map.left());
            int top = (int) Math.round(map.top());
            int width = (int) Math.round(image.getWidth() * map.scale());
            int height = (int) Math.round(image.getHeight() * map.scale());
            g.drawImage(image, left, top, width, height, null);
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.clipRect(left, top, width, height);
            drawRays(g, map);
        }
        g.dispose();
    }

    /**
     * The rays, each over a dark outline so that it shows on any colour: shadow rays dashed, a dot at each hit, and a
     * ring round the selected pixel, where the camera's ray starts.
     */
    private void drawRays(Graphics2D g, PixelMapping map) {
        for (boolean outline : new boolean[] {true, false}) {
            for (RayTreeProjection.Line line : rays) {
                boolean shadow = line.kind() == RayTree.Kind.SHADOW_LIT || line.kind() == RayTree.Kind.SHADOW_BLOCKED;
                float width = (shadow ? 1.5f : 2.5f) + (outline ? 2 : 0);
                g.setStroke(shadow ? new BasicStroke(width, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 1,
                        new float[] {6, 4}, 0) : new BasicStroke(width, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
                g.setColor(outline ? OUTLINE : colour(line.kind()));
                double x0 = map.panelX(line.x0());
                double y0 = map.panelY(line.y0());
                double x1 = map.panelX(line.x1());
                double y1 = map.panelY(line.y1());
                g.draw(new Line2D.Double(x0, y0, x1, y1));
                double dot = outline ? 5 : 3.5;
                if (line.ends() && !shadow) {
                    g.fill(new Ellipse2D.Double(x1 - dot, y1 - dot, 2 * dot, 2 * dot)); // the hit point
                }
                if (line.kind() == RayTree.Kind.CAMERA) {
                    g.setStroke(new BasicStroke(outline ? 4 : 2));
                    g.draw(new Ellipse2D.Double(x0 - 8, y0 - 8, 16, 16)); // the selected pixel
                }
            }
        }
    }

    private static Color colour(RayTree.Kind kind) {
        return switch (kind) {
            case CAMERA -> Color.WHITE;
            case REFLECTED -> new Color(80, 200, 255);
            case REFRACTED -> new Color(255, 120, 255);
            case SHADOW_LIT -> new Color(255, 230, 40);
            case SHADOW_BLOCKED -> new Color(150, 150, 150);
        };
    }

    /** The mouse: drag to orbit (right button or Shift: pan), wheel to zoom, click to select a pixel. */
    private final class Mouse extends MouseAdapter {

        private int pressX;
        private int pressY;
        private int lastX;
        private int lastY;
        private boolean dragged;
        /** The point a drag orbits around, fixed when the button is pressed. */
        private Vector3f pivot;

        @Override
        public void mousePressed(MouseEvent e) {
            requestFocusInWindow();
            pressX = lastX = e.getX();
            pressY = lastY = e.getY();
            dragged = false;
            pivot = session.pivot();
        }

        @Override
        public void mouseDragged(MouseEvent e) {
            PixelMapping map = mapping();
            if (map == null || (!dragged && Math.abs(e.getX() - pressX) + Math.abs(e.getY() - pressY) < 3)) {
                return; // a click that wobbles is still a click
            }
            dragged = true;
            boolean pan = SwingUtilities.isRightMouseButton(e)
                    || (e.getModifiersEx() & InputEvent.SHIFT_DOWN_MASK) != 0;
            session.drag((e.getX() - lastX) / map.scale(), (e.getY() - lastY) / map.scale(), pan, pivot);
            lastX = e.getX();
            lastY = e.getY();
            rest.restart();
        }

        @Override
        public void mouseReleased(MouseEvent e) {
            PixelMapping map = mapping();
            if (!dragged && map != null && SwingUtilities.isLeftMouseButton(e)) {
                session.select(map.pixelAt(e.getX(), e.getY()));
            }
        }

        @Override
        public void mouseMoved(MouseEvent e) {
            PixelMapping map = mapping();
            session.mouseAt(map == null ? null : map.pixelAt(e.getX(), e.getY()));
        }

        @Override
        public void mouseExited(MouseEvent e) {
            session.mouseAt(null);
        }

        @Override
        public void mouseWheelMoved(MouseWheelEvent e) {
            session.wheel(e.getPreciseWheelRotation());
            rest.restart();
        }
    }

    /**
     * Where the picture lies in the panel, and which pixel a point of the panel shows: the picture is scaled by one
     * factor to fit the panel (up or down, its shape kept) and centred in it. Image coordinates run from (0, 0), the
     * top left corner of pixel (0, 0), to (width, height); pixel (x, y) covers [x, x + 1) × [y, y + 1).
     *
     * @param scale screen pixels per image pixel
     */
    record PixelMapping(int imageWidth, int imageHeight, double scale, double left, double top) {

        static PixelMapping of(int imageWidth, int imageHeight, int panelWidth, int panelHeight) {
            double scale = panelWidth <= 0 || panelHeight <= 0 ? 1
                    : Math.min(panelWidth / (double) imageWidth, panelHeight / (double) imageHeight);
            return new PixelMapping(imageWidth, imageHeight, scale, (panelWidth - imageWidth * scale) / 2,
                    (panelHeight - imageHeight * scale) / 2);
        }

        /** The pixel {@code [x, y]} of the picture under the panel's point, or null outside the picture. */
        int[] pixelAt(double panelX, double panelY) {
            double x = Math.floor((panelX - left) / scale);
            double y = Math.floor((panelY - top) / scale);
            return x < 0 || y < 0 || x >= imageWidth || y >= imageHeight ? null : new int[] {(int) x, (int) y};
        }

        double panelX(double imageX) {
            return left + imageX * scale;
        }

        double panelY(double imageY) {
            return top + imageY * scale;
        }
    }
}
