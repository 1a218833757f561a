package rtd.cli;

import java.util.Locale;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/** Checks, before anything is allocated, that an image of the asked size fits in memory. */
final class ImageSize {

    /**
     * Bytes per pixel: the picture holds one {@code int} a pixel; {@code javax.imageio} writes it
     * from that array, row by row, and a spare 6 bytes a pixel leave room for the encoders that
     * convert the whole picture first.
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
            String advice = Memory.xmx(needed + runtime.maxMemory(), Memory.physical())
                    .map(xmx -> "choose a smaller --width/--height, or raise the limit: java -Xmx" + xmx + " -jar rtd.jar ...")
                    .orElse("choose a smaller --width/--height: this machine has " + Memory.size(Memory.physical()) + " in all");
            throw new ParameterException(commandLine, String.format(Locale.ROOT,
                    "a %d×%d image needs %s of memory, but Java may use only %s more here (limit %s); %s",
                    width, height, Memory.size(needed), Memory.size(available), Memory.size(runtime.maxMemory()), advice));
        }
    }
}
