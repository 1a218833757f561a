package rtd.cli;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/**
 * The pixel of {@code --explain X,Y}: two whole numbers, checked against the image's size, with
 * a message that names the size, since that is what a student needs to pick another pixel.
 *
 * @param x the column, from 0 at the left
 * @param y the row, from 0 at the top
 */
record PixelArgument(int x, int y) {

    private static final Pattern FORM = Pattern.compile("\\s*(\\d{1,9})\\s*,\\s*(\\d{1,9})\\s*");

    /** The pixel {@code value} names in a {@code width × height} image; a misuse (exit 2) if it names none. */
    static PixelArgument parse(String value, int width, int height, CommandLine commandLine) {
        String range = String.format("0 ≤ X < %d and 0 ≤ Y < %d (the image is %d × %d)", width, height, width, height);
        Matcher matcher = FORM.matcher(value);
        if (!matcher.matches()) {
            throw new ParameterException(commandLine, "--explain '" + value + "': give the pixel as X,Y, two whole numbers "
                    + "with " + range);
        }
        int x = Integer.parseInt(matcher.group(1));
        int y = Integer.parseInt(matcher.group(2));
        if (x >= width || y >= height) {
            throw new ParameterException(commandLine, "--explain " + x + "," + y + ": the pixel lies outside the image; "
                    + "choose " + range);
        }
        return new PixelArgument(x, y);
    }
}
