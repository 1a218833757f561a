package rtd.io;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.function.DoubleConsumer;
import javax.imageio.IIOException;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.event.IIOWriteProgressListener;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import rtd.image.Picture;

/**
 * The picture's file format, by the output's extension (whatever {@code javax.imageio} writes as RGB), and its
 * encoding of a {@link Picture}, whose array it hands over without a copy. PNG is known without starting
 * {@code javax.imageio} (slower than a small render).
 *
 * @param extension the extension in lower case, without the dot ("png", "jpg")
 */
public record ImageFormat(String extension) {

    /** What a name without extension, standard output and the default output get. */
    public static final ImageFormat PNG = new ImageFormat("png");
    private static final int[] RGB_MASKS = {0xFF0000, 0xFF00, 0xFF};

    /** The format for {@code output}: by its extension, PNG if it has none; empty if none can be written. */
    public static Optional<ImageFormat> forOutput(Path output) {
        Optional<String> extension = extensionOf(output);
        if (extension.isEmpty() || extension.get().equals(PNG.extension)) {
            return Optional.of(PNG);
        }
        return writerFor(extension.get()).isPresent() ? Optional.of(new ImageFormat(extension.get())) : Optional.empty();
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

    /** A writer for {@code extension} that encodes RGB without alpha (not WBMP's, black and white only). */
    private static Optional<ImageWriter> writerFor(String extension) {
        ImageTypeSpecifier rgb = ImageTypeSpecifier.createFromBufferedImageType(BufferedImage.TYPE_INT_RGB);
        // a loop, not a stream: every run passes here, and a first run would link a stream's lambdas for it
        for (Iterator<ImageWriter> writers = ImageIO.getImageWritersBySuffix(extension); writers.hasNext(); ) {
            ImageWriter writer = writers.next();
            if (writer.getOriginatingProvider().canEncodeImage(rgb)) {
                return Optional.of(writer);
            }
        }
        return Optional.empty();
    }

    /**
     * Loads this format's writer on a daemon thread by writing one pixel into nothing, then runs {@code then} there.
     * Wait for the result (which does not wait for {@code then}) before writing: two threads never load one class.
     */
    public CompletableFuture<Void> warmUp(Runnable then) {
        CompletableFuture<Void> done = new CompletableFuture<>();
        Thread thread = new Thread(() -> {
            try {
                write(new Picture(1, 1, new int[1]), OutputStream.nullOutputStream(), fraction -> { });
                done.complete(null);
            } catch (IOException | RuntimeException | Error e) {
                done.completeExceptionally(e); // the real write will meet it again, and say so
            }
            then.run();
        }, "rtd-warm-up");
        thread.setDaemon(true);
        thread.start();
        return done;
    }

    /** Writes {@code picture} to {@code out} (flushed, not closed), telling {@code progress} the fraction written. */
    public void write(Picture picture, OutputStream out, DoubleConsumer progress) throws IOException {
        ImageWriter writer = writerFor(extension)
                .orElseThrow(() -> new IllegalStateException("no writer for ." + extension));
        // In memory, not javax.imageio's default cache file in the system's temporary folder:
        // the writer seeks back only within the chunk it writes, which the cache keeps.
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.addIIOWriteProgressListener(new Progress(progress));
            ImageWriteParam parameters = writer.getDefaultWriteParam();
            // PNG at a low deflate level (quality 0.9), still lossless: half the time, a little larger
            if (extension.equals(PNG.extension) && parameters.canWriteCompressed()) {
                parameters.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
                parameters.setCompressionQuality(0.9f);
            }
            writer.write(null, new IIOImage(asImage(picture), null, null), parameters);
            stream.flush();
        } catch (IIOException e) {
            // javax.imageio wraps a failed write ("I/O error writing PNG file!"); the system's reason
            // ("No space left on device") is what a person needs
            throw e.getCause() instanceof IOException cause ? cause : e;
        } finally {
            writer.dispose();
        }
        out.flush();
    }

    /** The picture as an RGB image that shares its array, one int {@code 0xRRGGBB} a pixel. */
    static BufferedImage asImage(Picture picture) {
        DirectColorModel rgb = new DirectColorModel(24, RGB_MASKS[0], RGB_MASKS[1], RGB_MASKS[2]);
        DataBufferInt data = new DataBufferInt(picture.rgb(), picture.rgb().length);
        WritableRaster raster = Raster.createPackedRaster(data, picture.width(), picture.height(), picture.width(),
                RGB_MASKS, null);
        return new BufferedImage(rgb, raster, false, null);
    }

    private record Progress(DoubleConsumer fraction) implements IIOWriteProgressListener {
        @Override
        public void imageProgress(ImageWriter source, float percentageDone) {
            fraction.accept(percentageDone / 100.0);
        }

        @Override
        public void imageStarted(ImageWriter source, int imageIndex) {
            fraction.accept(0);
        }

        @Override
        public void imageComplete(ImageWriter source) {
            fraction.accept(1);
        }

        @Override
        public void thumbnailStarted(ImageWriter source, int imageIndex, int thumbnailIndex) {
        }

        @Override
        public void thumbnailProgress(ImageWriter source, float percentageDone) {
        }

        @Override
        public void thumbnailComplete(ImageWriter source) {
        }

        @Override
        public void writeAborted(ImageWriter source) {
        }
    }
}
