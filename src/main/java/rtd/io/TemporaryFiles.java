package rtd.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;

/**
 * The hidden temporary files {@code .NAME.<16 hex digits>.tmp} a picture is written to beside its output
 * before it is moved into place, removed after a failed write and by a shutdown hook when a signal stops the
 * JVM (only {@code kill -9} can leave one). Its list is global on purpose, as the hook belongs to the JVM
 * (guarded by this class's lock).
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
     * A new temporary file in {@code folder} for {@code outputName}, open for writing and remembered until
     * {@link #forget}; never one that exists.
     */
    static synchronized Created create(Path folder, String outputName) throws IOException {
        if (stopping) {
            throw new IOException("rtd is stopping");
        }
        // Not Files.createTempFile: its file may be read by its owner only, and would stay so.
        // A random name, not a UUID: that would start a SecureRandom, which takes long to seed.
        Path temporary = folder.resolve(name(outputName, ThreadLocalRandom.current().nextLong()));
        // CREATE_NEW: should the name be taken, fail rather than overwrite (or later delete) that file.
        OutputStream out = Files.newOutputStream(temporary, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        OPEN.add(temporary);
        return new Created(temporary, out);
    }

    /** A new temporary file and the stream that writes it. */
    record Created(Path path, OutputStream out) {
    }

    /** The temporary file is moved into place or deleted: the shutdown hook leaves it be. */
    static synchronized void forget(Path temporary) {
        OPEN.remove(temporary);
    }

    /** The name of a temporary file for {@code outputName}: {@code .NAME.<hex>.tmp}, NAME cut short if long. */
    static String name(String outputName, long random) {
        return "." + prefix(outputName, MAX_NAME_BYTES) + "." + String.format("%016x", random) + ".tmp";
    }

    /** The longest start of {@code name} that is at most {@code maxBytes} in UTF-8, cut between characters. */
    private static String prefix(String name, int maxBytes) {
        int bytes = 0;
        int end = 0;
        while (end < name.length()) {
            int codePoint = name.codePointAt(end);
            int size = new String(Character.toChars(codePoint)).getBytes(StandardCharsets.UTF_8).length;
            if (bytes + size > maxBytes) {
                break;
            }
            bytes += size;
            end += Character.charCount(codePoint);
        }
        return name.substring(0, end);
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
