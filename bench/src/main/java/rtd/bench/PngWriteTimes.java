package rtd.bench;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import rtd.image.Picture;
import rtd.io.ImageFormat;

/**
 * Where the write phase's time goes: writes one picture several times in one JVM into memory, as
 * rtd writes it ({@link ImageFormat#write}), and then with no compression at all (the JDK's PNG writer at
 * compression quality 1.0, which stores its rows without deflating them). What is left in the
 * second is the writer turning rows into bytes and choosing each row's filter.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar rtd.bench.PngWriteTimes bench/out/million.png 4
 * </pre>
 */
public final class PngWriteTimes {

    private PngWriteTimes() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: PngWriteTimes PICTURE.png TIMES");
            System.exit(2);
        }
        Picture picture = read(new File(args[0]));
        int times = Integer.parseInt(args[1]);
        for (int k = 1; k <= times; k++) {
            CountingStream out = new CountingStream();
            long start = System.nanoTime();
            ImageFormat.PNG.write(picture, out, fraction -> { });
            report("as rtd writes it", k, start, out.count);
        }
        BufferedImage image = picture.toBufferedImage();
        for (int k = 1; k <= times; k++) {
            CountingStream out = new CountingStream();
            long start = System.nanoTime();
            writeUncompressed(image, out);
            report("no compression", k, start, out.count);
        }
    }

    private static Picture read(File file) throws IOException {
        BufferedImage image = ImageIO.read(file);
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return new Picture(image.getWidth(), image.getHeight(), rgb);
    }

    private static void writeUncompressed(BufferedImage image, CountingStream out) throws IOException {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("png").next();
        ImageWriteParam parameters = writer.getDefaultWriteParam();
        parameters.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
        parameters.setCompressionQuality(1.0f);
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.write(null, new IIOImage(image, null, null), parameters);
        } finally {
            writer.dispose();
        }
    }

    private static void report(String how, int k, long start, long bytes) {
        System.out.printf("%-16s write %d: %6.1f ms, %,d bytes%n", how, k, (System.nanoTime() - start) / 1e6, bytes);
    }

    /** Counts the bytes written and keeps none. */
    private static final class CountingStream extends java.io.OutputStream {
        long count;

        @Override
        public void write(int b) {
            count++;
        }

        @Override
        public void write(byte[] bytes, int offset, int length) {
            count += length;
        }
    }
}
