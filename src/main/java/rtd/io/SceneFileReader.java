package rtd.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

/**
 * Reads a scene file into memory in bounded time and memory: a file over {@link SceneIO#MAX_SCENE_BYTES} is
 * refused before it is read, and a stream that never ends ({@code /dev/zero}, a pipe) is read in chunks,
 * each checked as it arrives, up to the first byte that is not text or the limit.
 */
final class SceneFileReader {

    private static final int CHUNK = 1 << 16;
    /** The most bytes of a regular file read at once ({@link #readWhole}). */
    private static final int WHOLE_FILE_PIECE = 1 << 20;

    private SceneFileReader() {
    }

    /**
     * The bytes of {@code path}, at most {@code limit}: all of them, or up to and including the chunk of the first
     * non-text byte.
     */
    static byte[] read(Path path, long limit) throws IOException {
        if (!Files.isRegularFile(path)) { // devices, FIFOs: of unknown length
            try (InputStream in = Files.newInputStream(path)) {
                return read(in, path.toString(), (int) limit);
            }
        }
        long size = Files.size(path);
        if (size > limit) {
            throw tooLarge(path.toString(), "is " + bytes(size), limit);
        }
        // A regular file of known size is bounded already: it is read whole, and the parser checks its text
        // before reading any statement.
        byte[] bytes = readWhole(path);
        if (bytes.length > limit) { // it grew while we read it
            throw tooLarge(path.toString(), "is larger than " + bytes(limit), limit);
        }
        return bytes;
    }

    /**
     * All bytes of the regular file {@code path}, read {@value #WHOLE_FILE_PIECE} bytes at a time: Java
     * keeps a buffer outside the heap as large as each read for the thread ({@code Files.readAllBytes} one
     * as large as the file).
     */
    static byte[] readWhole(Path path) throws IOException {
        try (InputStream in = Files.newInputStream(path)) {
            byte[] bytes = new byte[(int) Files.size(path)];
            int filled = 0;
            while (filled < bytes.length) {
                int read = in.read(bytes, filled, Math.min(WHOLE_FILE_PIECE, bytes.length - filled));
                if (read < 0) {
                    return Arrays.copyOf(bytes, filled); // it shrank while we read it
                }
                filled += read;
            }
            byte[] more = in.readAllBytes(); // what it grew by, in small reads
            byte[] all = more.length == 0 ? bytes : Arrays.copyOf(bytes, Math.addExact(bytes.length, more.length));
            System.arraycopy(more, 0, all, bytes.length, more.length);
            return all;
        }
    }

    /**
     * A stream of unknown length named {@code name}, read in chunks up to the first with a byte that is not
     * text, or past {@code limit} bytes.
     */
    static byte[] read(InputStream in, String name, int limit) throws IOException {
        byte[] bytes = new byte[Math.min(limit + 1, CHUNK)];
        int filled = 0;
        int checked = 0;
        while (true) {
            if (filled == bytes.length) {
                if (filled > limit) {
                    throw tooLarge(name, "is larger than " + bytes(limit), limit);
                }
                bytes = Arrays.copyOf(bytes, (int) Math.min(limit + 1L, 2L * bytes.length));
            }
            int read = in.read(bytes, filled, Math.min(CHUNK, bytes.length - filled));
            if (read < 0) {
                break;
            }
            filled += read;
            int whole = wholeCharacters(bytes, checked, filled);
            if (TextBytes.firstBadByte(bytes, checked, whole) >= 0) {
                break; // the rest cannot change the verdict: not a scene
            }
            checked = whole;
        }
        return filled == bytes.length ? bytes : Arrays.copyOf(bytes, filled);
    }

    private static FileSystemException tooLarge(String name, String size, long limit) {
        return new FileSystemException(name, null, "it " + size + "; rtd reads scene files of at most "
                + bytes(limit) + " (a scene of a million spheres is about 50 MiB)");
    }

    /** {@code bytes} in the largest binary unit that keeps a digit before the point: "3.0 GiB", "12.5 MiB". */
    private static String bytes(long bytes) {
        String[] units = {"bytes", "KiB", "MiB", "GiB", "TiB"};
        int unit = 0;
        double value = bytes;
        while (value >= 1024 && unit < units.length - 1) {
            value /= 1024;
            unit++;
        }
        return unit == 0 ? bytes + " bytes" : String.format(Locale.ROOT, "%.1f %s", value, units[unit]);
    }

    /** Where the whole characters of {@code bytes[from, to)} end: {@code to}, or the start of one cut at the end. */
    private static int wholeCharacters(byte[] bytes, int from, int to) {
        for (int i = to - 1; i >= Math.max(from, to - 3); i--) {
            int b = bytes[i] & 0xFF;
            if (b < 0x80) {
                return to;
            }
            if (b >= 0xC0) { // the first byte of a character of 2, 3 or 4 bytes
                return i + (b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : 2) > to ? i : to;
            }
        }
        return to;
    }
}
