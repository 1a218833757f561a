package rtd.view;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.function.DoubleToIntFunction;
import rtd.image.Picture;

/**
 * The scale of a view, written into the picture: a strip of {@value #HEIGHT} pixels below it
 * with a colour bar and its numbers, so that a picture shown alone still says what its colours
 * mean.
 */
final class Legend {

    /** The height of the strip added below the picture. */
    static final int HEIGHT = 32;
    private static final int MARGIN = 8;

    /** A number on the bar: its place, a share from 0 (left) to 1 (right), and its text. */
    record Tick(double share, String label) {
    }

    private Legend() {
    }

    /** {@code picture} with a strip below: the bar of {@code colours} from share 0 to 1, and the ticks. */
    static Picture below(Picture picture, DoubleToIntFunction colours, List<Tick> ticks) {
        int width = picture.width();
        int height = picture.height() + HEIGHT;
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, picture.height(), picture.rgb(), 0, width);
        int barWidth = Math.max(1, width - 2 * MARGIN);
        int left = Math.min(MARGIN, width - 1);
        for (int x = 0; x < width; x++) {
            for (int y = picture.height(); y < height; y++) {
                image.setRGB(x, y, 0x202020);
            }
        }
        for (int x = 0; x < barWidth && left + x < width; x++) {
            int colour = colours.applyAsInt(barWidth == 1 ? 0 : (double) x / (barWidth - 1));
            for (int y = picture.height() + 4; y < picture.height() + 14; y++) {
                image.setRGB(left + x, y, colour);
            }
        }
        drawTicks(image, picture.height(), left, barWidth, ticks);
        return Picture.of(image);
    }

    /**
     * The numbers under the bar. A machine without any font (some minimal servers) gets the bar
     * alone: the numbers are on standard error as well.
     */
    private static void drawTicks(BufferedImage image, int top, int left, int barWidth, List<Tick> ticks) {
        try {
            Graphics2D g = image.createGraphics();
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_OFF);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
            g.setColor(Color.WHITE);
            FontMetrics metrics = g.getFontMetrics();
            int lastEnd = Integer.MIN_VALUE;
            for (Tick tick : ticks) {
                int x = left + (int) Math.round(tick.share() * (barWidth - 1));
                g.drawLine(x, top + 14, x, top + 17);
                int textWidth = metrics.stringWidth(tick.label());
                int textLeft = Math.max(0, Math.min(image.getWidth() - textWidth, x - textWidth / 2));
                if (textLeft > lastEnd + 4) { // a label that would overlap the last one is left out
                    g.drawString(tick.label(), textLeft, top + 29);
                    lastEnd = textLeft + textWidth;
                }
            }
            g.dispose();
        } catch (RuntimeException | Error noFonts) {
            // no fonts: keep the bar
        }
    }
}
