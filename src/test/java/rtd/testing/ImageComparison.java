package rtd.testing;

import java.awt.image.BufferedImage;

/**
 * Compares two images pixel by pixel, either exactly or with the edge tolerance of the paper's
 * picture (README, "Tests"):
 * a pixel of the expected image is an edge pixel when one of its 8 neighbours has another
 * colour; a differing pixel must be an edge pixel and take the colour of one of its
 * neighbours in the expected image; and at most 2 % of the edge pixels may differ.
 */
public enum ImageComparison {
    EXACT,
    EDGE_TOLERANT;

    /** The share of edge pixels that may differ under {@link #EDGE_TOLERANT}. */
    public static final double MAX_EDGE_SHARE = 0.02;

    /** The outcome: counts, and a diff image (grey where equal, yellow tolerated, red not). */
    public record Result(boolean matches, String summary, BufferedImage diff) {
    }

    /** Compares {@code actual} with {@code expected} by this rule. */
    public Result compare(BufferedImage expected, BufferedImage actual) {
        int w = expected.getWidth();
        int h = expected.getHeight();
        if (actual.getWidth() != w || actual.getHeight() != h) {
            return new Result(false, "size " + actual.getWidth() + "×" + actual.getHeight()
                    + ", expected " + w + "×" + h, null);
        }
        BufferedImage diff = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        long edgePixels = 0;
        long tolerated = 0;
        long wrong = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int want = expected.getRGB(x, y) & 0xFFFFFF;
                int got = actual.getRGB(x, y) & 0xFFFFFF;
                boolean edge = isEdge(expected, x, y);
                edgePixels += edge ? 1 : 0;
                if (want == got) {
                    diff.setRGB(x, y, dim(want));
                } else if (this == EDGE_TOLERANT && edge && neighbourHas(expected, x, y, got)) {
                    tolerated++;
                    diff.setRGB(x, y, 0xFFFF00);
                } else {
                    wrong++;
                    diff.setRGB(x, y, 0xFF0000);
                }
            }
        }
        boolean tooMany = tolerated > MAX_EDGE_SHARE * edgePixels;
        String summary = String.format("%d pixels differ beyond the tolerance, %d differing edge pixels tolerated of %d edge pixels (at most %.0f %%)",
                wrong, tolerated, edgePixels, MAX_EDGE_SHARE * 100);
        return new Result(wrong == 0 && !tooMany, summary, diff);
    }

    private static boolean isEdge(BufferedImage image, int x, int y) {
        int colour = image.getRGB(x, y);
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int nx = x + dx;
                int ny = y + dy;
                if ((dx != 0 || dy != 0) && inside(image, nx, ny) && image.getRGB(nx, ny) != colour) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean neighbourHas(BufferedImage image, int x, int y, int rgb) {
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int nx = x + dx;
                int ny = y + dy;
                if ((dx != 0 || dy != 0) && inside(image, nx, ny) && (image.getRGB(nx, ny) & 0xFFFFFF) == rgb) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean inside(BufferedImage image, int x, int y) {
        return x >= 0 && y >= 0 && x < image.getWidth() && y < image.getHeight();
    }

    private static int dim(int rgb) {
        int grey = (((rgb >> 16) & 0xFF) + ((rgb >> 8) & 0xFF) + (rgb & 0xFF)) / 3;
        int light = 128 + grey / 2;
        return (light << 16) | (light << 8) | light;
    }
}
