package rtd.window;

import rtd.image.Picture;

/**
 * The window's picture while it is refined: a coarse pass renders one pixel per block of {@code block × block} pixels
 * (8, then 4, 2 and 1: {@link Refinement}), and each block is filled with its pixel's colour, so the picture shows at
 * once and sharpens. The last pass, blocks of 1, sets every pixel itself: the picture is then the full render's.
 */
final class ProgressiveBuffer {

    private final int width;
    private final int height;
    private final int[] rgb;

    ProgressiveBuffer(int width, int height) {
        this.width = width;
        this.height = height;
        this.rgb = new int[width * height];
    }

    /** How many blocks of {@code block} pixels cover {@code size} pixels: the last block may be cut off. */
    static int blocks(int size, int block) {
        return (size + block - 1) / block;
    }

    /** Fills each block of {@code block × block} pixels with its pixel of {@code coarse}, one pixel per block. */
    void put(int block, Picture coarse) {
        if (coarse.width() != blocks(width, block) || coarse.height() != blocks(height, block)) {
            throw new IllegalArgumentException("a pass of blocks of " + block + " of a " + width + " × " + height
                    + " picture has " + blocks(width, block) + " × " + blocks(height, block) + " pixels, not "
                    + coarse.width() + " × " + coarse.height());
        }
        for (int y = 0; y < height; y++) {
            int row = y / block * coarse.width();
            for (int x = 0; x < width; x++) {
                rgb[y * width + x] = coarse.rgb()[row + x / block];
            }
        }
    }

    /** A copy of the picture as it is now. */
    Picture picture() {
        return new Picture(width, height, rgb.clone());
    }
}
