package rtd.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;

/**
 * The hidden temporary files {@code .NAME.<16 hex digits>.tmp} a picture or an animation is written to beside
 * its output before it is moved into place, so that the output is written all or nothing: removed after a
 * failed write and by a shutdown hook when a signal stops the JVM (only {@code kill -9} can leave one). Its
 * list is global on purpose, as the hook belongs to the JVM (guarded by this class's lock).
 */
final class TemporaryFiles {

    /**
     * The most bytes of the output's name kept in the temporary name: with the 22 bytes added it stays
     * within the 255 that most file systems allow.
     */
    static final int MAX_NAME_BYTES = 200;

    private static final Set<Path> OPEN = new HashSet<>();
    private static boolean stopping;

    static {
        try {
            Runtime.getRuntime().addShutdownHook(new Thread(TemporaryFiles::removeAll, "rtd: remove temporary files"));
        } catch (IllegalStateException e) {
            stopping = true; // the JVM is already stopping: create() then refuses
        }
    }

    private TemporaryFiles() {
    }

    /**
     * A new temporary file beside {@code output}, open for writing and removed by the shutdown hook until it
     * is committed or discarded; never one that exists.
     */
    static synchronized Replacement create(Path output) throws IOException {
        if (stopping) {
            throw new IOException("rtd is stopping");
        }
        Path folder = output.toAbsolutePath().getParent();
        // Not Files.createTempFile: its file may be read by its owner only, and would stay so.
        // A random name, not a UUID: that would start a SecureRandom, which takes long to seed.
        Path temporary = folder.resolve(name(output.getFileName().toString(), ThreadLocalRandom.current().nextLong()));
        // CREATE_NEW: should the name be taken, fail rather than overwrite (or later delete) that file.
        OutputStream out = Files.newOutputStream(temporary, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        OPEN.add(temporary);
        return new Replacement(temporary, output, out);
    }

    /**
     * A temporary file being written, and the output it replaces once complete: all or nothing.
     *
     * @param path   the temporary file
     * @param output the file it becomes
     * @param out    the stream that writes it
     */
    record Replacement(Path path, Path output, OutputStream out) {

        /** Moves the written file over the output (atomically where the file system can). */
        void commit() throws IOException {
            try {
                Files.move(path, output, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(path, output, StandardCopyOption.REPLACE_EXISTING);
            }
            forget(path);
        }

        /** Closes and deletes the temporary file; the output stays as it was. */
        void discard() throws IOException {
            try {
                out.close();
            } finally {
                Files.deleteIfExists(path);
                forget(path);
            }
        }
    }

    private static synchronized void forget(Path temporary) {
        OPEN.remove(temporary);
    }

    /** The name of a temporary file for {@code outputName}: {@code .NAME.<hex>.tmp}, NAME cut short if long. */
    static String name(String outputName, long random) {
        return "." + prefix(outputName, MAX_NAME_BYTES) + "." + String.format("%016x", random) + ".tmp";
    }

    /** The longest start of {@code name} that is at most {@code maxBytes} in UTF-8, cut between characters. */
    private static String prefix(String name, int maxBytes) {
        byte[] bytes = name.getBytes(StandardCharsets.UTF_8);
        int cut = Math.min(bytes.length, maxBytes);
        while (cut < bytes.length && cut > 0 && (bytes[cut] & 0xC0) == 0x80) {
            cut--; // not inside a character of several bytes
        }
        return new String(bytes, 0, cut, StandardCharsets.UTF_8);
    }

    private static synchronized void removeAll() {
        stopping = true;
        for (Path temporary : OPEN) {
            try {
                Files.deleteIfExists(temporary);
            } catch (IOException e) {
                // the JVM is stopping: nothing more can be done, and the folder may be gone
            }
        }
        OPEN.clear();
    }
}
