package rtd.cli;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.function.DoubleConsumer;
import rtd.image.Picture;
import rtd.io.ImageFormat;
import rtd.io.SceneIO;

/**
 * Where a file rtd writes goes, decided before rendering on the real file, links followed: a regular file that a
 * complete new one replaces, or a FIFO or character device written into; never the scene, a device or a link itself.
 *
 * @param spelt the output as the user gave it, for messages
 * @param file  where to write: for {@link Kind#REPLACE} the real file, whose folder holds the temporary file
 */
record OutputTarget(Path spelt, Path file, Kind kind) {

    /** A regular file, new or old, replaced by a complete new one; a FIFO or character device; {@code -o -}. */
    enum Kind { REPLACE, STREAM, STANDARD_OUTPUT }

    static final Path DASH = Path.of("-");

    /** Writes {@code picture} here in {@code format}, telling {@code progress} the fraction done. */
    void write(Picture picture, ImageFormat format, OutputStream standardOutput, DoubleConsumer progress)
            throws FileError {
        try {
            switch (kind) {
                case STREAM -> SceneIO.writeImageInto(picture, format, file, progress);
                case REPLACE -> SceneIO.writeImage(picture, format, file, progress);
                case STANDARD_OUTPUT -> format.write(picture, new BufferedOutputStream(standardOutput, 1 << 16),
                        progress);
            }
        } catch (IOException e) {
            if (kind == Kind.STANDARD_OUTPUT && "broken pipe".equalsIgnoreCase(String.valueOf(e.getMessage()))) {
                throw new FileError("cannot write the picture to standard output: the program reading it stopped "
                        + "before the end (broken pipe)");
            }
            throw new FileError("cannot write '" + spelt + "'", e);
        }
    }

    /** Writes {@code text} here in UTF-8. */
    void writeText(String text) throws FileError {
        try {
            if (kind == Kind.STREAM) {
                Files.writeString(file, text, StandardCharsets.UTF_8, StandardOpenOption.WRITE);
            } else {
                SceneIO.writeText(text, file);
            }
        } catch (IOException e) {
            throw new FileError("cannot write '" + spelt + "'", e);
        }
    }

    /** Where {@code spelt}, named by {@code option}, goes; else a misuse (exit 2) or a file that may not be written. */
    static OutputTarget of(Path spelt, Path scene, String option) throws FileError {
        OutputTarget target = find(spelt, scene, option);
        Path folder = target.file.toAbsolutePath().getParent();
        String wrong = target.kind != Kind.REPLACE ? null : !Files.isDirectory(folder) ? (Files.exists(folder)
                ? "is a file, not a folder" : "does not exist") : !Files.isWritable(folder) ? "is not writable" : null;
        if (wrong != null) {
            throw new FileError("cannot write '" + spelt + "': the folder '" + folder + "' " + wrong);
        }
        Path real = target.file.getFileName();
        // a link to a file of another kind, such as a mesh or notes: a slip, and replacing it would destroy it
        Misuse.refuse(target.kind == Kind.REPLACE && "-o".equals(option) && real != null
                && !real.equals(spelt.getFileName()) && !(ImageFormat.extensionOf(target.file).isPresent()
                        && ImageFormat.forOutput(target.file).equals(ImageFormat.forOutput(spelt))), "'" + spelt
                + "' leads to '" + target.file + "', whose name is not that of a ."
                + ImageFormat.forOutput(spelt).map(ImageFormat::extension).orElse("png")
                + " picture; rtd writes through a link only into a picture of the kind asked for");
        return target;
    }

    private static OutputTarget find(Path output, Path scene, String option) throws FileError {
        Misuse.refuse(Files.isDirectory(output), "the output '" + output + "' is a folder; give a "
                + "file name such as " + output.resolve("out.png"));
        if (!Files.exists(output)) {
            if (Files.isSymbolicLink(output)) {
                throw new FileError("cannot write '" + output + "': it is a symbolic link to '" + linkTarget(output)
                        + "', which does not exist");
            }
            return new OutputTarget(output, output, Kind.REPLACE);
        }
        Misuse.refuse(isSameFile(output, scene), "the output '" + output + "' is the scene file "
                + "itself; choose another with " + option);
        String notAFile = switch (fileType(output)) {
            case 0100000 -> null;
            case 0010000, 0020000 -> "";
            case 0060000 -> "a block device (a disk)";
            case 0140000 -> "a socket";
            default -> "not a regular file";
        };
        if (notAFile == null) {
            try {
                return new OutputTarget(output, output.toRealPath(), Kind.REPLACE);
            } catch (IOException e) {
                throw new FileError("cannot write '" + output + "'", e);
            }
        }
        Misuse.refuse(!notAFile.isEmpty(), "the output '" + output + "' is " + notAFile + "; rtd "
                + "writes the picture to a file, a FIFO or a character device such as /dev/null");
        return new OutputTarget(output, output, Kind.STREAM);
    }

    /** The file-type bits of the mode (Linux, macOS); without a "unix" view (Windows), regular file or not. */
    private static int fileType(Path path) {
        try {
            return (Integer) Files.getAttribute(path, "unix:mode") & 0170000;
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
            return Files.isRegularFile(path) ? 0100000 : 0;
        }
    }

    /** Whether both name one file, after links; spelt paths decide only when a file is missing. */
    private static boolean isSameFile(Path output, Path scene) {
        try {
            return Files.exists(scene) && Files.isSameFile(output, scene);
        } catch (IOException e) {
            return output.toAbsolutePath().normalize().equals(scene.toAbsolutePath().normalize());
        }
    }

    private static String linkTarget(Path link) {
        try {
            return Files.readSymbolicLink(link).toString();
        } catch (IOException e) {
            return "?";
        }
    }
}
