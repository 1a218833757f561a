package rtd.io;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.zip.Adler32;
import java.util.zip.CRC32;
import java.util.zip.Deflater;
import rtd.image.Picture;

/**
 * Encodes a {@link Picture} as a 24-bit RGB PNG (the PNG specification, ISO/IEC 15948).
 *
 * <p>Why not {@code javax.imageio}: starting it loads Java's imaging toolkit, which takes
 * longer than rendering the paper's example, and it compresses on one core. This encoder
 * uses only {@link Deflater} (zlib), cuts the picture into strips of rows and compresses the
 * strips side by side. The strips are always the same, whatever the number of threads, so
 * the file is the same byte for byte.
 *
 * <p>A PNG is a signature and a list of chunks: IHDR (size and pixel format), IDAT (the
 * pixels as one zlib stream, here one chunk a strip) and IEND. Each row is stored as it is
 * (filter type 0): rtd's pictures are flat areas of colour, which zlib packs well as they are.
 */
final class PngEncoder {

    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    /** The zlib header for deflate with a 32 KiB window at the fastest level (RFC 1950). */
    private static final byte[] ZLIB_HEADER = {0x78, 0x01};
    private static final int ROWS_PER_STRIP = 64;
    private static final byte FILTER_NONE = 0;

    private PngEncoder() {
    }

    /** Writes {@code picture} as a PNG to {@code out}, compressing with up to {@code threads} threads. */
    static void write(Picture picture, OutputStream out, int threads) throws IOException {
        DataOutputStream data = new DataOutputStream(out);
        data.write(SIGNATURE);
        writeChunk(data, "IHDR", header(picture));
        List<Strip> strips = compressStrips(picture, threads);
        Adler32 checksum = new Adler32();
        for (int i = 0; i < strips.size(); i++) {
            Strip strip = strips.get(i);
            checksum.update(strip.rows());
            ByteArrayOutputStream idat = new ByteArrayOutputStream(strip.compressed().length + 6);
            if (i == 0) {
                idat.write(ZLIB_HEADER);
            }
            idat.write(strip.compressed());
            if (i == strips.size() - 1) {
                new DataOutputStream(idat).writeInt((int) checksum.getValue());
            }
            writeChunk(data, "IDAT", idat.toByteArray());
        }
        writeChunk(data, "IEND", new byte[0]);
        data.flush();
    }

    private static byte[] header(Picture picture) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(13);
        DataOutputStream header = new DataOutputStream(bytes);
        header.writeInt(picture.width());
        header.writeInt(picture.height());
        header.writeByte(8); // bits per sample
        header.writeByte(2); // colour type: RGB
        header.writeByte(0); // compression: deflate
        header.writeByte(0); // filter method: the standard five filters
        header.writeByte(0); // no interlacing
        return bytes.toByteArray();
    }

    /** A chunk: length, type, data, and a CRC-32 of type and data. */
    private static void writeChunk(DataOutputStream out, String type, byte[] data) throws IOException {
        byte[] typeBytes = type.getBytes(StandardCharsets.US_ASCII);
        CRC32 crc = new CRC32();
        crc.update(typeBytes);
        crc.update(data);
        out.writeInt(data.length);
        out.write(typeBytes);
        out.write(data);
        out.writeInt((int) crc.getValue());
    }

    /** Some rows as PNG stores them, and the same compressed. */
    private record Strip(byte[] rows, byte[] compressed) {
    }

    private static List<Strip> compressStrips(Picture picture, int threads) throws IOException {
        int count = (picture.height() + ROWS_PER_STRIP - 1) / ROWS_PER_STRIP;
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Math.min(threads, count)), runnable -> {
            Thread thread = new Thread(runnable, "rtd-png");
            thread.setDaemon(true);
            return thread;
        });
        try {
            List<Future<Strip>> futures = new ArrayList<>();
            for (int i = 0; i < count; i++) {
                int firstRow = i * ROWS_PER_STRIP;
                int endRow = Math.min(picture.height(), firstRow + ROWS_PER_STRIP);
                boolean last = i == count - 1;
                futures.add(pool.submit(() -> compress(rows(picture, firstRow, endRow), last)));
            }
            List<Strip> strips = new ArrayList<>();
            for (Future<Strip> future : futures) {
                strips.add(future.get());
            }
            return strips;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while compressing the picture", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("compressing the picture failed", e.getCause());
        } finally {
            pool.shutdownNow();
        }
    }

    /** Rows {@code firstRow} to {@code endRow − 1}, each a filter byte and then R, G, B per pixel. */
    private static byte[] rows(Picture picture, int firstRow, int endRow) {
        int width = picture.width();
        int[] rgb = picture.rgb();
        byte[] rows = new byte[(endRow - firstRow) * (1 + 3 * width)];
        int at = 0;
        for (int y = firstRow; y < endRow; y++) {
            rows[at++] = FILTER_NONE;
            for (int i = y * width; i < (y + 1) * width; i++) {
                int pixel = rgb[i];
                rows[at++] = (byte) (pixel >> 16);
                rows[at++] = (byte) (pixel >> 8);
                rows[at++] = (byte) pixel;
            }
        }
        return rows;
    }

    /**
     * Deflates one strip on its own. Every strip but the last ends with a sync flush, which
     * ends on a whole byte without ending the stream, so the strips joined in order are one
     * valid deflate stream (as pigz does it).
     */
    private static Strip compress(byte[] rows, boolean last) {
        Deflater deflater = new Deflater(Deflater.BEST_SPEED, true);
        try {
            deflater.setInput(rows);
            if (last) {
                deflater.finish();
            }
            ByteArrayOutputStream compressed = new ByteArrayOutputStream(rows.length / 8 + 64);
            byte[] buffer = new byte[1 << 16];
            int flush = last ? Deflater.NO_FLUSH : Deflater.SYNC_FLUSH;
            while (true) {
                int length = deflater.deflate(buffer, 0, buffer.length, flush);
                compressed.write(buffer, 0, length);
                boolean done = last ? deflater.finished() : length < buffer.length && deflater.needsInput();
                if (done) {
                    return new Strip(rows, compressed.toByteArray());
                }
            }
        } finally {
            deflater.end();
        }
    }
}
