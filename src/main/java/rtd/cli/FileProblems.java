package rtd.cli;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;

/** Turns a failed file operation into one sentence for a person. */
final class FileProblems {

    private FileProblems() {
    }

    static String describe(IOException e) {
        if (e instanceof NoSuchFileException missing) {
            return missing.getReason() != null
                    ? missing.getReason() + ": " + missing.getFile()
                    : "no such file: " + missing.getFile();
        }
        if (e instanceof AccessDeniedException denied) {
            return (denied.getReason() != null ? denied.getReason() : "permission denied") + ": " + denied.getFile();
        }
        if (e instanceof NotDirectoryException notFolder) {
            return "not a folder: " + notFolder.getFile();
        }
        if (e instanceof FileSystemException fileSystem && fileSystem.getFile() != null) {
            String reason = fileSystem.getReason() != null ? fileSystem.getReason() : "cannot be used";
            return fileSystem.getFile() + ": " + reason;
        }
        return e.getMessage() != null ? e.getMessage() : e.toString();
    }
}
