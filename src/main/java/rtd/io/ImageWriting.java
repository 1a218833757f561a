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
import java.util.concurrent.CompletableFuture;
import java.util.function.DoubleConsumer;
import javax.imageio.IIOException;
import javax.imageio.IIOImage;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.event.IIOWriteProgressListener;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import rtd.image.Picture;

/**
 * Encodes a {@link Picture} through {@code javax.imageio} in its {@link ImageFormat}, handing over its array
 * without a copy as RGB without alpha.
 */
public final class ImageWriting {

    private static final int[] RGB_MASKS = {0xFF0000, 0xFF00, 0xFF};

    private ImageWriting() {
    }

    /**
     * Starts {@code javax.imageio} and the writer of {@code format} on a daemon thread (loading it takes
     * longer than a small render) by writing one pixel into nothing, then runs {@code then} on that thread.
     * Wait for the result (which does not wait for {@code then}) before writing, so that two threads never
     * load the same classes.
     */
    public static CompletableFuture<Void> warmUp(ImageFormat format, Runnable then) {
        CompletableFuture<Void> done = new CompletableFuture<>();
        Thread thread = new Thread(() -> {
            try {
                write(new Picture(1, 1, new int[1]), format, OutputStream.nullOutputStream(), fraction -> { });
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
    public static void write(Picture picture, ImageFormat format, OutputStream out, DoubleConsumer progress)
            throws IOException {
        ImageWriter writer = format.newWriter();
        // In memory, not javax.imageio's default cache file in the system's temporary folder:
        // the writer seeks back only within the chunk it writes, which the cache keeps.
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.addIIOWriteProgressListener(new Progress(progress));
            writer.write(null, new IIOImage(asImage(picture), null, null), parameters(writer, format));
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

    /** The defaults, but for PNG a low deflate level (quality 0.9), still lossless: half the time, a little larger. */
    private static ImageWriteParam parameters(ImageWriter writer, ImageFormat format) {
        ImageWriteParam parameters = writer.getDefaultWriteParam();
        if (format.isPng() && parameters.canWriteCompressed()) {
            parameters.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            parameters.setCompressionQuality(0.9f);
        }
        return parameters;
    }

    /** The picture as an RGB image that shares its array, laid out so that the writer reads it fast ({@link PackedRgbSamples}). */
    static BufferedImage asImage(Picture picture) {
        DirectColorModel rgb = new DirectColorModel(24, RGB_MASKS[0], RGB_MASKS[1], RGB_MASKS[2]);
        DataBufferInt data = new DataBufferInt(picture.rgb(), picture.rgb().length);
        WritableRaster raster = Raster.createWritableRaster(new PackedRgbSamples(picture.width(), picture.height()),
                data, null);
        return new BufferedImage(rgb, raster, false, null);
    }

    /** Passes the writer's percentage on as a fraction. */
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
     * A {@link Picture}'s layout, one int {@code 0xRRGGBB} a pixel, row by row, whose {@link #getPixels}
     * reads the array directly: the JDK's goes through the data buffer's methods, slow before the JIT
     * compiles them. The samples are the same.
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
