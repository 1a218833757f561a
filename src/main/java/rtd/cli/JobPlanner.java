package rtd.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import rtd.io.ImageFormat;

/**
 * Where each scene's picture goes and in which format, checked before any rendering: a mistake on the command line
 * stops the run before any work, and a long render does not end in a failed write.
 *
 * @param output the picture that {@code -o} names, or null for each scene's default
 */
record JobPlanner(Path output, StandardStreams streams) {

    /** A scene with where its picture goes, or the file error (reported in its turn) for why it cannot go there. */
    record Job(SceneSource source, OutputTarget target, ImageFormat format, FileError refusal) {
    }

    /** Each scene's job, in order; one picture name cannot serve several scenes. */
    List<Job> jobs(List<Path> scenes) {
        List<SceneSource> sources = scenes.stream().map(SceneSource::of).toList();
        Misuse.refuse(output != null && sources.size() > 1, "-o names one picture, but "
                + sources.size() + " scenes were given; leave -o out to write each picture beside its scene");
        Misuse.refuse(output == null && sources.stream().anyMatch(SceneSource::stdin), "the scene '-' "
                + "comes from standard input, which gives no name for the picture; name it with -o, such as "
                + "-o out.png, or -o - for standard output");
        List<Job> jobs = new ArrayList<>();
        Map<Path, SceneSource> writers = new HashMap<>();
        Map<Object, SceneSource> files = new HashMap<>();
        for (SceneSource source : sources) {
            Misuse.refuse(!source.stdin() && files.putIfAbsent(fileKey(source.path()), source) != null,
                    "the scene '" + source.name() + "' is given twice (or a link to it is); give it once");
            try {
                OutputTarget target = outputTarget(source);
                // ball.txt and an editor's ball.txt~ both give ball.png: the second would replace the first's
                SceneSource earlier = target.kind() != OutputTarget.Kind.REPLACE ? null
                        : writers.putIfAbsent(realPlace(target.file()), source);
                Misuse.refuse(earlier != null, "the scenes '" + (earlier == null ? "" : earlier.name())
                        + "' and '" + source.name() + "' would both write their picture to '" + target.spelt()
                        + "', the second replacing the first; render them in separate runs with -o, or rename one");
                jobs.add(new Job(source, target, format(target), null));
            } catch (FileError e) {
                jobs.add(new Job(source, null, ImageFormat.PNG, e));
            }
        }
        return jobs;
    }

    /** The format of {@code target}'s extension; one that no writer knows is a mistake on the command line. */
    static ImageFormat format(OutputTarget target) {
        ImageFormat format = ImageFormat.forOutput(target.spelt()).orElse(null);
        if (format == null) { // the writers' list only for the message: asking every writer takes a while
            String extension = ImageFormat.extensionOf(target.spelt()).orElse("");
            throw new Misuse("the output '" + target.spelt() + "' ends in '." + extension + "', a format rtd "
                    + "cannot write; give it one of "
                    + ImageFormat.writableExtensions().stream().map(e -> "." + e).collect(Collectors.joining(", ")));
        }
        return format;
    }

    /** Where the picture goes: {@code -o}, or the scene's name with {@code .png}. */
    private OutputTarget outputTarget(SceneSource source) throws FileError {
        if (!source.stdin() && Files.isDirectory(source.path())) { // before the default output, which / has no name for
            throw new FileError("cannot read the scene file '" + source.name() + "': it is a folder, not a file");
        }
        if (OutputTarget.DASH.equals(output)) {
            Misuse.refuse(streams.outIsTerminal(), "-o - writes the picture to standard output, which "
                    + "is a terminal here; send it to a file or a program instead, such as: " + RtdCommand.NAME
                    + " scene.txt -o - > out.png");
            return new OutputTarget(OutputTarget.DASH, OutputTarget.DASH, OutputTarget.Kind.STANDARD_OUTPUT);
        }
        if (output == null && !source.stdin() && isPngPicture(source.path())) { // else refused as the scene file
            throw new FileError("cannot read the scene file '" + source.name() + "': it is a PNG picture, not a scene; "
                    + "give rtd the scene's text file, such as examples/input_rtd.txt");
        }
        Path spelt = output != null ? output : defaultOutput(source.path(), "");
        return OutputTarget.of(spelt, source.stdin() ? streams.inPath().orElse(source.path()) : source.path(), "-o");
    }

    /** Where {@code file} is, after the links on the way to its folder (it need not exist yet). */
    private static Path realPlace(Path file) {
        Path absolute = file.toAbsolutePath().normalize();
        try {
            return Files.exists(absolute) ? absolute.toRealPath()
                    : absolute.getParent().toRealPath().resolve(absolute.getFileName());
        } catch (IOException | RuntimeException e) {
            return absolute; // a folder that cannot be reached: the write will say so
        }
    }

    /** What tells one file from another, however it is named (its inode, where the system says); else its path. */
    private static Object fileKey(Path file) {
        try {
            Object key = Files.readAttributes(file, BasicFileAttributes.class).fileKey();
            return key != null ? key : file.toRealPath();
        } catch (IOException | RuntimeException e) {
            return file.toAbsolutePath().normalize(); // missing or unreadable: reading it will say so
        }
    }

    /** Whether {@code file} is a regular file that starts as a PNG does (not a FIFO: its bytes are the reader's). */
    private static boolean isPngPicture(Path file) {
        byte[] signature = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
        try (InputStream in = Files.isRegularFile(file) ? Files.newInputStream(file) : InputStream.nullInputStream()) {
            return Arrays.equals(in.readNBytes(signature.length), signature);
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /** {@code a.txt} gives {@code a.png}, with {@code suffix} "-cost" {@code a-cost.png}; {@code a} {@code a.png}. */
    static Path defaultOutput(Path scene, String suffix) {
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return scene.resolveSibling((dot > 0 ? name.substring(0, dot) : name) + suffix + ".png");
    }
}
