package rtd.cli;

import java.io.IOException;

/** A file that cannot be read or written (exit code 1); the message says which and why. */
final class FileError extends Exception {
    private static final long serialVersionUID = 1L;

    FileError(String message, IOException cause) {
        super(message, cause);
    }
}
