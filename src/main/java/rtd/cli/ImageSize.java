package rtd.cli;

import java.util.Locale;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/** Checks, before anything is allocated, that an image of the asked size fits in memory. */
final class ImageSize {

    /**
     * Bytes per pixel: the picture holds one {@code int} a pixel; writing the PNG adds its rows
     * (3 bytes a pixel) and, at worst, as much again compressed.
     */
    private static final long BYTES_PER_PIXEL = 4 + 3 + 3;

    private ImageSize() {
    }

    static void check(CommandLine commandLine, int width, int height) {
        long pixels = (long) width * height;
        if (pixels > Integer.MAX_VALUE - 8) {
            throw new ParameterException(commandLine, String.format(Locale.ROOT,
                    "a %d×%d image has %,d pixels; Java images hold at most %,d", width, height, pixels,
                    Integer.MAX_VALUE - 8));
        }
        Runtime runtime = Runtime.getRuntime();
        long available = runtime.maxMemory() - (runtime.totalMemory() - runtime.freeMemory());
        long needed = pixels * BYTES_PER_PIXEL;
        if (needed > available) {
            throw new ParameterException(commandLine, String.format(Locale.ROOT,
                    "a %d×%d image needs %s of memory, but Java may use only %s more here (limit %s); "
                            + "choose a smaller --width/--height, or raise the limit: java -Xmx%dg -jar rtd.jar ...",
                    width, height, gib(needed), gib(available), gib(runtime.maxMemory()),
                    (needed + runtime.maxMemory()) / (1L << 30) + 1));
        }
    }

    private static String gib(long bytes) {
        return String.format(Locale.ROOT, "%.1f GiB", bytes / (double) (1L << 30));
    }
}
