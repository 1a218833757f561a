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
        String reason = e instanceof FileSystemException failure && failure.getReason() != null ? failure.getReason()
                : e instanceof NoSuchFileException ? "no such file" : e instanceof AccessDeniedException
                ? "permission denied" : e instanceof NotDirectoryException ? "not a folder"
                : e.getMessage() != null ? e.getMessage() : "an input/output error"; // "No space left on device"
        return reason.isEmpty() ? reason : reason.substring(0, 1).toLowerCase(Locale.ROOT) + reason.substring(1);
    }
}
