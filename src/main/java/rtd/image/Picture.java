package rtd.image;

import java.awt.image.BufferedImage;

/**
 * A rendered picture: {@code width × height} pixels, row by row from the top left, each
 * packed as {@code 0xRRGGBB} (the layout of {@link rtd.image.Color#getRGB}).
 *
 * <p>It is a plain array rather than a {@link BufferedImage} so that rendering a picture needs
 * none of Java's imaging toolkit ({@code java.awt}), which is slow to start.
 * The array is shared, not copied: the renderer fills it, and after that it is only read.
 *
 * @param width  pixels per row
 * @param height rows
 * @param rgb    the pixels; pixel (x, y) is at {@code y * width + x}
 */
public record Picture(int width, int height, int[] rgb) {

    /** Checks that the array holds exactly {@code width × height} pixels. */
    public Picture {
        if (width <= 0 || height <= 0 || rgb.length != (long) width * height) {
            throw new IllegalArgumentException("a " + width + " × " + height + " picture needs that many pixels, not "
                    + rgb.length);
        }
    }

    /** The colour of pixel (x, y) as {@code 0xRRGGBB}. */
    public int rgb(int x, int y) {
        return rgb[y * width + x];
    }

    /** The pixels of {@code image}, without the alpha channel that {@link BufferedImage#getRGB} adds. */
    public static Picture of(BufferedImage image) {
        int width = image.getWidth();
        int height = image.getHeight();
        int[] rgb = image.getRGB(0, 0, width, height, null, 0, width);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return new Picture(width, height, rgb);
    }

    /** A copy as a {@link BufferedImage}, for Java's imaging classes (tests, other programs). */
    public BufferedImage toBufferedImage() {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, rgb, 0, width);
        return image;
    }
}
