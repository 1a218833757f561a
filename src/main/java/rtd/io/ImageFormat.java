package rtd.io;

import java.awt.image.BufferedImage;
import java.awt.image.DataBuffer;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.SampleModel;
import java.awt.image.SinglePixelPackedSampleModel;
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
        return writerFor(extension.get()).map(writer -> new ImageFormat(extension.get()));
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
        ImageWriter writer = writerFor(extension).orElseThrow(); // forOutput made this format only if one exists
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

    /** The picture as an RGB image that shares its array, laid out so that the writer reads it fast. */
    static BufferedImage asImage(Picture picture) {
        DirectColorModel rgb = new DirectColorModel(24, RGB_MASKS[0], RGB_MASKS[1], RGB_MASKS[2]);
        DataBufferInt data = new DataBufferInt(picture.rgb(), picture.rgb().length);
        WritableRaster raster = Raster.createWritableRaster(new PackedRgbSamples(picture.width(), picture.height()),
                data, null);
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

    /**
     * A {@link Picture}'s layout, one int {@code 0xRRGGBB} a pixel, whose {@link #getPixels} reads the array
     * directly: the JDK's goes through the data buffer's methods, slow before the JIT compiles them.
     */
    static final class PackedRgbSamples extends SinglePixelPackedSampleModel {

        PackedRgbSamples(int width, int height) {
            super(DataBuffer.TYPE_INT, width, height, RGB_MASKS);
        }

        /** The same layout at another size: the PNG writer copies each row into a raster of its own first. */
        @Override
        public SampleModel createCompatibleSampleModel(int width, int height) {
            return new PackedRgbSamples(width, height);
        }

        @Override
        public int[] getPixels(int x, int y, int w, int h, int[] samples, DataBuffer data) {
            if (!(data instanceof DataBufferInt ints) || ints.getNumBanks() != 1 || x < 0 || y < 0 || w < 0 || h < 0
                    || x + w > getWidth() || y + h > getHeight()) {
                return super.getPixels(x, y, w, h, samples, data); // as the JDK does it, with its checks
            }
            int[] into = samples != null ? samples : new int[3 * w * h];
            int[] rgb = ints.getData();
            int width = getScanlineStride();
            int k = 0;
            for (int row = y; row < y + h; row++) {
                int from = ints.getOffset() + row * width + x;
                for (int i = from; i < from + w; i++) {
                    int pixel = rgb[i];
                    into[k] = pixel >>> 16 & 0xFF;
                    into[k + 1] = pixel >>> 8 & 0xFF;
                    into[k + 2] = pixel & 0xFF;
                    k += 3;
                }
            }
            return into;
        }
    }
}
