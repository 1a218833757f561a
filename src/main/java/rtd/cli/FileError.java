package rtd.cli;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.util.Locale;

/** A file that cannot be read or written (exit code 1); the message says which and why, in words for people. */
final class FileError extends Exception {
    private static final long serialVersionUID = 1L;

    FileError(String message) {
        super(message);
    }

    /** {@code what} ("cannot write 'out.png'") and why {@code e} happened. */
    FileError(String what, IOException e) {
        super(what + ": " + reason(e), e);
    }

    /** Why {@code e} happened, without Java's exception names: "no such file", "permission denied". */
    static String reason(IOException e) {
        if (e instanceof FileSystemException failure && failure.getReason() != null) {
            return lowerFirst(failure.getReason()); // the system's "No such file", not rtd's "3.0 GiB"
        }
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NotDirectoryException) {
            return "not a folder";
        }
        return e.getMessage() != null ? lowerFirst(e.getMessage()) : "an input/output error"; // "No space left on device"
    }

    private static String lowerFirst(String text) {
        return text.isEmpty() ? text : text.substring(0, 1).toLowerCase(Locale.ROOT) + text.substring(1);
    }
}
