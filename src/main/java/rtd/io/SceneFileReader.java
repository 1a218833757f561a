package rtd.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

/**
 * Reads a scene file into memory in bounded time and memory, whatever the file is: a file larger
 * than {@link SceneIO#MAX_SCENE_BYTES} is refused before it is read, one within it is read whole,
 * and a stream that never ends
 * ({@code /dev/zero}, a pipe) is read in chunks, each checked as it arrives, so that reading stops
 * at the first chunk with a byte that is not text (a NUL byte, bytes that are not UTF-8), or once
 * the stream has grown past the limit. The parser then names that byte, with its line and column.
 */
final class SceneFileReader {

    private static final int CHUNK = 1 << 16;
    /** The most bytes of a regular file read at once ({@link #readWhole}). */
    private static final int WHOLE_FILE_PIECE = 1 << 20;

    private SceneFileReader() {
    }

    /** The bytes of {@code path}: all of them, or up to and including the chunk of the first non-text byte. */
    static byte[] read(Path path) throws IOException {
        return read(path, SceneIO.MAX_SCENE_BYTES);
    }

    /** As {@link #read(Path)}, with a limit of {@code limit} bytes (at most {@link SceneIO#MAX_SCENE_BYTES}). */
    static byte[] read(Path path, long limit) throws IOException {
        long size = Files.isRegularFile(path) ? Files.size(path) : -1; // devices, FIFOs: unknown
        if (size > limit) {
            throw tooLarge(path, "is " + bytes(size), limit);
        }
        if (size >= 0) {
            // A regular file of known size is bounded already: read it without checking each
            // chunk (the parser checks its text in parallel parts), which is faster for a large
            // scene than chunks of 64 KiB.
            byte[] bytes = readWhole(path, size);
            if (bytes.length > limit) { // it grew while we read it
                throw tooLarge(path, "is larger than " + bytes(limit), limit);
            }
            return bytes;
        }
        try (InputStream in = Files.newInputStream(path)) {
            return read(path, in, size, (int) limit);
        }
    }

    /**
     * All bytes of the regular file {@code path}, which had {@code size} of them (more if it
     * grew meanwhile), read {@value #WHOLE_FILE_PIECE} bytes at a time: Java reads a file into
     * an array through a buffer outside the heap as large as each read, and keeps that buffer
     * for the thread ({@code Files.readAllBytes} of a million spheres kept 50 MB for the whole
     * run).
     */
    static byte[] readWhole(Path path) throws IOException {
        return readWhole(path, Files.size(path));
    }

    /** {@link #readWhole(Path)} of a file that had {@code size} bytes. */
    private static byte[] readWhole(Path path, long size) throws IOException {
        try (InputStream in = Files.newInputStream(path)) {
            byte[] bytes = new byte[(int) size];
            int filled = 0;
            while (filled < bytes.length) {
                int read = in.read(bytes, filled, Math.min(WHOLE_FILE_PIECE, bytes.length - filled));
                if (read < 0) {
                    return Arrays.copyOf(bytes, filled); // it shrank while we read it
                }
                filled += read;
            }
            byte[] more = in.readAllBytes(); // what it grew by, in small reads
            if (more.length == 0) {
                return bytes;
            }
            byte[] all = Arrays.copyOf(bytes, Math.addExact(bytes.length, more.length));
            System.arraycopy(more, 0, all, bytes.length, more.length);
            return all;
        }
    }

    private static byte[] read(Path path, InputStream in, long size, int limit) throws IOException {
        // One byte more than the size, so that a file that grew while read is noticed without a copy.
        byte[] bytes = new byte[(int) Math.min(limit + 1L, size >= 0 ? size + 1 : CHUNK)];
        TextCheck check = new TextCheck();
        int filled = 0;
        while (true) {
            if (filled == bytes.length) {
                if (filled > limit) {
                    throw tooLarge(path, "is larger than " + bytes(limit), limit);
                }
                bytes = Arrays.copyOf(bytes, (int) Math.min(limit + 1L, 2L * bytes.length));
            }
            int read = in.read(bytes, filled, Math.min(CHUNK, bytes.length - filled));
            if (read < 0) {
                break;
            }
            filled += read;
            if (!check.isText(bytes, filled - read, filled)) {
                break; // the rest cannot change the verdict: not a scene
            }
        }
        return filled == bytes.length ? bytes : Arrays.copyOf(bytes, filled);
    }

    private static FileSystemException tooLarge(Path path, String size, long limit) {
        return new FileSystemException(path.toString(), null, "it " + size + "; rtd reads scene files of at most "
                + bytes(limit) + " (a scene of a million spheres is about 50 MiB)");
    }

    /** {@code bytes} in the largest binary unit that keeps a digit before the point: "3.0 GiB", "12.5 MiB". */
    static String bytes(long bytes) {
        String[] units = {"bytes", "KiB", "MiB", "GiB", "TiB"};
        int unit = 0;
        double value = bytes;
        while (value >= 1024 && unit < units.length - 1) {
            value /= 1024;
            unit++;
        }
        return unit == 0 ? bytes + " bytes" : String.format(Locale.ROOT, "%.1f %s", value, units[unit]);
    }

    /**
     * Whether the bytes read so far are text: no NUL byte, and UTF-8 as far as it is complete (a
     * character may be cut at the end of a chunk; its rest comes with the next).
     */
    private static final class TextCheck {
        private final CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
        private final CharBuffer scratch = CharBuffer.allocate(CHUNK);
        /** The bytes before this are whole, valid characters. */
        private int checked;

        /** Checks the chunk {@code bytes[from, to)}, after all bytes before it. */
        boolean isText(byte[] bytes, int from, int to) {
            boolean ascii = true;
            for (int i = from; i < to; i++) {
                if (bytes[i] == 0) {
                    return false;
                }
                ascii &= bytes[i] > 0;
            }
            if (ascii && checked == from) {
                checked = to; // the usual scene: no need to decode
                return true;
            }
            ByteBuffer in = ByteBuffer.wrap(bytes, checked, to - checked);
            CoderResult result;
            do {
                scratch.clear();
                result = decoder.decode(in, scratch, false);
            } while (result.isOverflow());
            checked = in.position();
            return !result.isError();
        }
    }
}
