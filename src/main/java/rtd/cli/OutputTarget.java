package rtd.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Where the picture goes, decided before rendering: the file that a new picture replaces, or a
 * FIFO or character device that it is written into.
 *
 * <p>Decided on the real file, not on the path as spelt: a symbolic link (the output itself or a
 * folder on the way) is followed, so that neither the scene file nor a device nor the link
 * itself is ever replaced.
 *
 * @param spelt the output as the user gave it, for messages
 * @param file  where to write: for {@link Kind#REPLACE} the real file (links followed), whose
 *              folder holds the temporary file; for {@link Kind#STREAM} the path as given
 * @param kind  how to write
 */
record OutputTarget(Path spelt, Path file, Kind kind) {

    /** How the picture reaches the output. */
    enum Kind {
        /** A regular file, new or old: written to a temporary file, then moved into place. */
        REPLACE,
        /** A FIFO or character device such as /dev/null: the picture is written into it as it is. */
        STREAM,
        /** {@code -o -}: standard output, which must not be a terminal. */
        STANDARD_OUTPUT
    }

    /** The name by which {@code -o} names standard output. */
    static final Path DASH = Path.of("-");

    /** Standard output, for {@code -o -}. */
    static OutputTarget standardOutput() {
        return new OutputTarget(DASH, DASH, Kind.STANDARD_OUTPUT);
    }

    /** What kind of file a path names, by the file-type bits of its mode (Linux, macOS). */
    private enum FileType {
        REGULAR, FIFO, CHARACTER_DEVICE, BLOCK_DEVICE, SOCKET, UNKNOWN;

        static FileType of(Path path) {
            try {
                int mode = (Integer) Files.getAttribute(path, "unix:mode");
                return switch (mode & 0170000) {
                    case 0100000 -> REGULAR;
                    case 0010000 -> FIFO;
                    case 0020000 -> CHARACTER_DEVICE;
                    case 0060000 -> BLOCK_DEVICE;
                    case 0140000 -> SOCKET;
                    default -> UNKNOWN;
                };
            } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
                // No "unix" view (Windows): a regular file is still told apart; anything else is refused.
                return Files.isRegularFile(path) ? REGULAR : UNKNOWN;
            }
        }
    }

    /**
     * What {@code output} is, or why rtd may not write it: a {@link Refusal} that the command
     * line turns into a message. The scene file is {@code scene}; {@code option} names the output
     * in messages ({@code -o}, {@code --export-pov}).
     */
    static OutputTarget of(Path output, Path scene, String option) throws Refusal {
        if (Files.isDirectory(output)) {
            throw Refusal.misuse("the output '" + output + "' is a folder; give a file name such as " + output.resolve("out.png"));
        }
        if (!Files.exists(output)) {
            if (Files.isSymbolicLink(output)) {
                throw Refusal.fileError("cannot write '" + output + "': it is a symbolic link to '" + linkTarget(output)
                        + "', which does not exist");
            }
            return new OutputTarget(output, output, Kind.REPLACE);
        }
        if (isSameFile(output, scene)) {
            throw Refusal.misuse("the output '" + output + "' is the scene file itself; choose another with " + option);
        }
        return switch (FileType.of(output)) {
            case REGULAR -> new OutputTarget(output, realPath(output), Kind.REPLACE);
            case FIFO, CHARACTER_DEVICE -> new OutputTarget(output, output, Kind.STREAM);
            case BLOCK_DEVICE -> throw notAFile(output, "a block device (a disk)");
            case SOCKET -> throw notAFile(output, "a socket");
            case UNKNOWN -> throw notAFile(output, "not a regular file");
        };
    }

    /** The folder that must exist and be writable: the one the temporary file goes to. */
    Optional<Path> folder() {
        return kind == Kind.REPLACE ? Optional.of(file.toAbsolutePath().getParent()) : Optional.empty();
    }

    private static Refusal notAFile(Path output, String what) {
        return Refusal.misuse("the output '" + output + "' is " + what
                + "; rtd writes the picture to a file, a FIFO or a character device such as /dev/null");
    }

    /** Whether both name one file, after links; spelt paths decide only when a file is missing. */
    private static boolean isSameFile(Path output, Path scene) {
        try {
            return Files.exists(scene) && Files.isSameFile(output, scene);
        } catch (IOException e) {
            return output.toAbsolutePath().normalize().equals(scene.toAbsolutePath().normalize());
        }
    }

    private static Path realPath(Path output) throws Refusal {
        try {
            return output.toRealPath();
        } catch (IOException e) {
            throw Refusal.fileError("cannot write '" + output + "': " + FileProblems.reason(e));
        }
    }

    private static String linkTarget(Path link) {
        try {
            return Files.readSymbolicLink(link).toString();
        } catch (IOException e) {
            return "?";
        }
    }

    /** Why the output may not be written; {@link #misuse} is a mistake on the command line (exit 2). */
    static final class Refusal extends Exception {
        private static final long serialVersionUID = 1L;
        private final boolean misuse;

        private Refusal(String message, boolean misuse) {
            super(message, null, false, false);
            this.misuse = misuse;
        }

        static Refusal misuse(String message) {
            return new Refusal(message, true);
        }

        static Refusal fileError(String message) {
            return new Refusal(message, false);
        }

        boolean misuse() {
            return misuse;
        }
    }
}
