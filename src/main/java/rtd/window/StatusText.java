package rtd.window;

import java.util.Locale;

/**
 * The window's status line: the last frame's render time, its rays per second, the picture's size and the pixel under
 * the mouse, with what the picture shows (and at which clock) and how coarse it is still.
 */
final class StatusText {

    private StatusText() {
    }

    /** The clock as the status line and the slider's label write it: {@code clock 0.250}. */
    static String clock(double clock) {
        return String.format(Locale.ROOT, "clock %.3f", clock);
    }

    /**
     * The line for a frame of {@code width × height} that took {@code nanos} for {@code rays} rays, in blocks of
     * {@code block} pixels; {@code pixel} the one under the mouse or null; {@code shows} "picture" or a view's name.
     */
    static String of(int width, int height, long nanos, long rays, int block, int[] pixel, String shows) {
        double seconds = nanos / 1e9;
        String rate = seconds > 0 ? String.format(Locale.ROOT, "%.2f Mrays/s", rays / seconds / 1e6) : "–";
        String blocks = block > 1 ? String.format(Locale.ROOT, " (blocks of %d × %d)", block, block) : "";
        String under = pixel == null ? "" : String.format(Locale.ROOT, " · pixel (%d, %d)", pixel[0], pixel[1]);
        return String.format(Locale.ROOT, "%s · %d × %d%s · last frame %.3f s · %s%s", shows, width, height, blocks,
                seconds, rate, under);
    }
}
