package rtd.io;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleConsumer;
import rtd.image.Picture;
import rtd.scene.Scene;

/**
 * Input and output (paper, sections 4.1 and 4.3): reads a scene file at clock 0, writes a picture in an
 * {@link ImageFormat} or a text, whole or not at all. A file is read in bounded time and memory: one over
 * {@link #MAX_SCENE_BYTES} is refused unread, and a stream of unknown length ({@code /dev/zero}, a pipe) is read
 * in chunks, each checked as it arrives, up to the first non-text byte.
 */
public final class SceneIO {

    /** The name of standard input in messages, as compilers call it. */
    public static final String STDIN_NAME = "<stdin>";
    /** The largest scene file rtd reads, 1 GiB: about 20 million spheres. */
    public static final long MAX_SCENE_BYTES = 1L << 30;
    /** How many bytes of a stream are read, or buffered to be written, at once. */
    private static final int CHUNK = 1 << 16;
    /** The most bytes of a regular file read at once: Java keeps a buffer outside the heap as large as each read. */
    private static final int WHOLE_FILE_PIECE = 1 << 20;

    private SceneIO() {
    }

    /** Reads the scene file at {@code path}, without its warnings; its meshes are found from its folder. */
    public static Scene readScene(Path path) throws SceneException, IOException {
        return SceneFile.read(path).once(null);
    }

    /** Reads a scene from {@code text}, named {@code name} in messages; meshes are found from the current directory. */
    public static Scene parseScene(String name, String text) throws SceneException {
        return parseScene(name, text.getBytes(StandardCharsets.UTF_8), Path.of(""), null);
    }

    /** Reads a scene from {@code bytes}, its meshes found from {@code meshFolder}, adding its warnings to a list. */
    public static Scene parseScene(String name, byte[] bytes, Path meshFolder, List<SceneError> warnings)
            throws SceneException {
        return SceneFile.of(name, bytes, meshFolder).once(warnings);
    }

    /** Writes {@code picture} to {@code output} all or nothing, through a temporary file ({@link TemporaryFiles}). */
    public static void writeImage(Picture picture, ImageFormat format, Path output, DoubleConsumer progress)
            throws IOException {
        TemporaryFiles.replace(output, out -> format.write(picture, out, progress));
    }

    /** Writes {@code text} in UTF-8 to {@code output} as {@link #writeImage} writes a picture: whole, or not at all. */
    public static void writeText(String text, Path output) throws IOException {
        // Encoded as it is written, not as one array: the export of a large scene is tens of megabytes.
        TemporaryFiles.replace(output, out -> new OutputStreamWriter(out, StandardCharsets.UTF_8).append(text).flush());
    }

    /** Writes {@code picture} into {@code device}, a FIFO or /dev/null: never created, replaced or truncated. */
    public static void writeImageInto(Picture picture, ImageFormat format, Path device, DoubleConsumer progress)
            throws IOException {
        try (OutputStream into = Files.newOutputStream(device, StandardOpenOption.WRITE);
                OutputStream out = new BufferedOutputStream(into, CHUNK)) {
            format.write(picture, out, progress);
        }
    }

    /** The bytes of {@code path}, at most {@code limit}: all, or up to the chunk of the first non-text byte. */
    static byte[] readBytes(Path path, long limit) throws IOException {
        if (!Files.isRegularFile(path)) { // devices, FIFOs: of unknown length
            try (InputStream in = Files.newInputStream(path)) {
                return readBytes(in, path.toString(), (int) limit);
            }
        }
        long size = Files.size(path);
        if (size > limit) {
            throw tooLarge(path.toString(), "is " + bytes(size), limit);
        }
        byte[] bytes = readWhole(path); // bounded already: read whole; the parse checks its text
        if (bytes.length > limit) { // it grew while we read it
            throw tooLarge(path.toString(), "is larger than " + bytes(limit), limit);
        }
        return bytes;
    }

    /** All bytes of a regular file, in pieces: {@code Files.readAllBytes} keeps a buffer as large as the file. */
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

    /** A stream of unknown length, read in chunks up to the first with a non-text byte, or past {@code limit}. */
    static byte[] readBytes(InputStream in, String name, int limit) throws IOException {
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
            if (SourceText.firstBadByte(bytes, checked, whole) >= 0) {
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
        int unit = bytes < 1024 ? 0 : Math.min(4, (63 - Long.numberOfLeadingZeros(bytes)) / 10);
        return unit == 0 ? bytes + " bytes"
                : String.format(Locale.ROOT, "%.1f %s", bytes / Math.pow(1024, unit), "KMGT".charAt(unit - 1) + "iB");
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
