package rtd.io;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriter;

/**
 * The picture's file format, by the output's extension: {@code .png}, {@code .jpg}, {@code .bmp}, whatever
 * {@code javax.imageio} writes for RGB. PNG is known without starting {@code javax.imageio} (slower than a
 * small render); any other is looked up at once, so that one it cannot write is a command-line mistake.
 *
 * @param extension the extension in lower case, without the dot ("png", "jpg")
 */
public record ImageFormat(String extension) {

    /** PNG: lossless, and what a name without extension, standard output and the default output get. */
    public static final ImageFormat PNG = new ImageFormat("png");

    /** The format for {@code output}: by its extension, PNG if it has none; empty if none can be written. */
    public static Optional<ImageFormat> forOutput(Path output) {
        Optional<String> extension = extensionOf(output);
        if (extension.isEmpty() || extension.get().equals(PNG.extension)) {
            return Optional.of(PNG);
        }
        return writerFor(extension.get()).isPresent() ? Optional.of(new ImageFormat(extension.get())) : Optional.empty();
    }

    /** Whether this is {@link #PNG}, by the extension: the record's first {@code equals} sets up method handles. */
    public boolean isPng() {
        return extension.equals(PNG.extension);
    }

    /** The extensions (lower case, sorted) whose format {@code javax.imageio} can write an RGB picture in. */
    public static List<String> writableExtensions() {
        return Arrays.stream(ImageIO.getWriterFileSuffixes()).map(suffix -> suffix.toLowerCase(Locale.ROOT))
                .filter(extension -> !extension.isEmpty() && writerFor(extension).isPresent())
                .distinct().sorted().toList();
    }

    /** The extension of the last name of {@code path} ("a.b.PNG" gives "png"); none for "a" and ".hidden". */
    public static Optional<String> extensionOf(Path path) {
        Path name = path.getFileName();
        String text = name == null ? "" : name.toString();
        int dot = text.lastIndexOf('.');
        return dot > 0 && dot < text.length() - 1 ? Optional.of(text.substring(dot + 1).toLowerCase(Locale.ROOT))
                : Optional.empty();
    }

    /** A new writer of this format for an RGB picture. */
    ImageWriter newWriter() {
        return writerFor(extension).orElseThrow(() -> new IllegalStateException("no writer for ." + extension));
    }

    /** A writer for {@code extension} that encodes RGB without alpha (not WBMP's, black and white only). */
    private static Optional<ImageWriter> writerFor(String extension) {
        ImageTypeSpecifier rgb = ImageTypeSpecifier.createFromBufferedImageType(BufferedImage.TYPE_INT_RGB);
        Iterator<ImageWriter> writers = ImageIO.getImageWritersBySuffix(extension);
        while (writers.hasNext()) {
            ImageWriter writer = writers.next();
            if (writer.getOriginatingProvider().canEncodeImage(rgb)) {
                return Optional.of(writer);
            }
        }
        return Optional.empty();
    }
}
