package rtd.io;

import java.io.BufferedOutputStream;
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
 * The hidden temporary files {@code .NAME.<16 hex digits>.tmp} beside an output, moved into place once written,
 * so that the output is written all or nothing: removed after a failed write and by a shutdown hook (only
 * {@code kill -9} can leave one). Its list is global on purpose, as the hook belongs to the JVM.
 */
final class TemporaryFiles {

    /** The most bytes of the output's name kept: with the 22 bytes added it stays within most file systems' 255. */
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

    interface Writing {
        void into(OutputStream out) throws IOException;
    }

    /** Writes {@code output} with {@code writing} through a temporary file: whole, or not at all. */
    static void replace(Path output, Writing writing) throws IOException {
        Replacement temporary = create(output);
        try {
            try (OutputStream out = new BufferedOutputStream(temporary.out(), 1 << 16)) {
                writing.into(out);
            }
            temporary.commit();
        } catch (IOException | RuntimeException | Error e) {
            temporary.discard();
            throw e;
        }
    }

    /** A new temporary file beside {@code output}, open for writing; never one that exists. */
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

    /** A temporary file at {@code path} being written by {@code out}, and the {@code output} it replaces. */
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

        /** Closes and deletes the temporary file. */
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
        byte[] bytes = outputName.getBytes(StandardCharsets.UTF_8);
        int cut = Math.min(bytes.length, MAX_NAME_BYTES);
        while (cut < bytes.length && cut > 0 && (bytes[cut] & 0xC0) == 0x80) {
            cut--; // not inside a character of several bytes
        }
        return "." + new String(bytes, 0, cut, StandardCharsets.UTF_8) + "." + String.format("%016x", random) + ".tmp";
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
