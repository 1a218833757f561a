package rtd.window;

/**
 * Where the picture lies in the window's panel, and which pixel a point of the panel shows: the picture is scaled by
 * one factor to fit the panel (up or down, its shape kept) and centred in it. Image coordinates run from (0, 0), the
 * top left corner of pixel (0, 0), to (width, height); pixel (x, y) covers [x, x + 1) × [y, y + 1).
 *
 * @param imageWidth  the picture's width in pixels
 * @param imageHeight the picture's height in pixels
 * @param panelWidth  the panel's width in screen pixels
 * @param panelHeight the panel's height in screen pixels
 */
record PixelMapping(int imageWidth, int imageHeight, int panelWidth, int panelHeight) {

    /** Screen pixels per image pixel. */
    double scale() {
        if (panelWidth <= 0 || panelHeight <= 0) {
            return 1;
        }
        return Math.min(panelWidth / (double) imageWidth, panelHeight / (double) imageHeight);
    }

    double left() {
        return (panelWidth - imageWidth * scale()) / 2;
    }

    double top() {
        return (panelHeight - imageHeight * scale()) / 2;
    }

    /** The pixel {@code [x, y]} of the picture under the panel's point, or null outside the picture. */
    int[] pixelAt(double panelX, double panelY) {
        double x = Math.floor((panelX - left()) / scale());
        double y = Math.floor((panelY - top()) / scale());
        if (x < 0 || y < 0 || x >= imageWidth || y >= imageHeight) {
            return null;
        }
        return new int[] {(int) x, (int) y};
    }

    /** The panel's x of the image's x coordinate. */
    double panelX(double imageX) {
        return left() + imageX * scale();
    }

    /** The panel's y of the image's y coordinate. */
    double panelY(double imageY) {
        return top() + imageY * scale();
    }
}
