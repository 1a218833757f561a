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
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import rtd.io.ImageFormat;

/**
 * Where each picture goes and in which format ({@link Job}), all checked before any rendering,
 * so that a mistake on the command line stops the run before any work, and a long render does
 * not end in a failed write. {@link RtdCommand} plans its scenes' jobs with it, from {@code -o}
 * and the standard streams.
 */
final class JobPlanner {

    /** The picture that {@code -o} names, or null for each scene's default. */
    private final Path output;
    private final StandardStreams streams;
    /** The command line, for the misuses (exit code 2) a plan can find. */
    private final CommandLine commandLine;

    JobPlanner(Path output, StandardStreams streams, CommandLine commandLine) {
        this.output = output;
        this.streams = streams;
        this.commandLine = commandLine;
    }

    /** Each scene's job, in order: a target and format, or the file error that refuses it. */
    List<Job> jobs(List<SceneSource> sources) {
        List<Job> jobs = new ArrayList<>();
        Map<Path, SceneSource> writers = new HashMap<>();
        Map<Object, SceneSource> scenes = new HashMap<>();
        for (SceneSource source : sources) {
            if (!source.stdin() && scenes.putIfAbsent(fileKey(source.path()), source) != null) {
                throw misuse("the scene '" + source.name() + "' is given twice (or a link to it is); give it once");
            }
            try {
                OutputTarget target = outputTarget(source);
                checkNotWrittenTwice(source, target, writers);
                jobs.add(new Job(source, target, format(target, commandLine), null));
            } catch (FileError e) {
                jobs.add(new Job(source, null, ImageFormat.PNG, e));
            }
        }
        return jobs;
    }

    /**
     * Two scenes of one run whose pictures would go to one file ({@code ball.txt} and an editor's
     * {@code ball.txt~} both give {@code ball.png}): the second would silently replace the first's.
     */
    private void checkNotWrittenTwice(SceneSource source, OutputTarget target, Map<Path, SceneSource> writers) {
        if (target.kind() != OutputTarget.Kind.REPLACE) {
            return; // a device or standard output takes what it is given
        }
        SceneSource earlier = writers.putIfAbsent(realPlace(target.file()), source);
        if (earlier != null) {
            throw misuse("the scenes '" + earlier.name() + "' and '" + source.name() + "' would both write their picture to '"
                    + target.spelt() + "', the second replacing the first; render them in separate runs with -o, or "
                    + "rename one");
        }
    }

    /**
     * The format of {@code target}'s extension (also for {@code --view}); an extension that no
     * writer knows is a mistake on the command line.
     */
    static ImageFormat format(OutputTarget target, CommandLine commandLine) {
        return ImageFormat.forOutput(target.spelt()).orElseThrow(() -> new ParameterException(commandLine,
                "the output '" + target.spelt() + "' ends in '." + ImageFormat.extensionOf(target.spelt()).orElse("")
                        + "', a format rtd cannot write; give it one of " + ImageFormat.writableExtensions().stream()
                                .map(e -> "." + e).collect(Collectors.joining(", "))));
    }

    /**
     * Where the picture goes: {@code -o}, or the scene's name with {@code .png}; checked before
     * rendering, on the real files behind any symbolic link, so that nothing but a regular file
     * is ever replaced.
     */
    private OutputTarget outputTarget(SceneSource source) throws FileError {
        if (!source.stdin() && Files.isDirectory(source.path())) {
            // before the default output, which a folder such as / has no name for
            throw new FileError("cannot read the scene file '" + source.name() + "': it is a folder, not a file", null);
        }
        if (OutputTarget.DASH.equals(output)) {
            if (streams.outIsTerminal()) {
                throw misuse("-o - writes the picture to standard output, which is a terminal here; send it to a file "
                        + "or a program instead, such as: " + RtdCommand.NAME + " scene.txt -o - > out.png");
            }
            return OutputTarget.standardOutput();
        }
        if (output == null && !source.stdin() && isPngPicture(source.path())) {
            // else its picture would be named as itself, and refused as the scene file
            throw new FileError("cannot read the scene file '" + source.name() + "': it is a PNG picture, not a scene; "
                    + "give rtd the scene's text file, such as examples/input_rtd.txt", null);
        }
        Path spelt = output != null ? output : defaultOutput(source.path());
        return target(spelt, source.stdin() ? streams.inPath().orElse(source.path()) : source.path(), "-o", commandLine);
    }

    /**
     * The file that {@code option} names ({@code -o}, a view's {@code -o}, {@code --export-pov}),
     * by the rules of {@link OutputTarget}, with its folder there and writable: a mistake on the
     * command line is thrown as such, a file that may not be written as a {@link FileError}.
     */
    static OutputTarget target(Path spelt, Path scene, String option, CommandLine commandLine) throws FileError {
        OutputTarget target;
        try {
            target = OutputTarget.of(spelt, scene, option);
        } catch (OutputTarget.Refusal refusal) {
            if (refusal.misuse()) {
                throw new ParameterException(commandLine, refusal.getMessage());
            }
            throw new FileError(refusal.getMessage(), null);
        }
        if (target.folder().isPresent()) {
            checkFolder(spelt, target.folder().get());
        }
        Path real = target.file().getFileName();
        if (target.kind() == OutputTarget.Kind.REPLACE && "-o".equals(option) && real != null
                && !real.equals(spelt.getFileName()) && !samePictureKind(spelt, target.file())) {
            // a link to a file of another kind, such as a mesh or notes: a slip, and replacing it would destroy it
            throw new ParameterException(commandLine, "'" + spelt + "' leads to '" + target.file() + "', whose name "
                    + "is not that of a ." + ImageFormat.forOutput(spelt).map(ImageFormat::extension).orElse("png")
                    + " picture; rtd writes through a link only into a picture of the kind asked for");
        }
        return target;
    }

    private ParameterException misuse(String message) {
        return new ParameterException(commandLine, message);
    }

    /** That {@code folder}, where the file {@code spelt} goes, exists and may be written to. */
    private static void checkFolder(Path spelt, Path folder) throws FileError {
        if (!Files.isDirectory(folder)) {
            throw new FileError("cannot write '" + spelt + "': the folder '" + folder + "' "
                    + (Files.exists(folder) ? "is a file, not a folder" : "does not exist"), null);
        }
        if (!Files.isWritable(folder)) {
            throw new FileError("cannot write '" + spelt + "': the folder '" + folder + "' is not writable", null);
        }
    }

    /** Whether the real file behind a link has an extension, and one of the same format as the name given. */
    private static boolean samePictureKind(Path spelt, Path real) {
        return ImageFormat.extensionOf(real).isPresent()
                && ImageFormat.forOutput(real).equals(ImageFormat.forOutput(spelt));
    }

    /** Where {@code file} is, after the links on the way to its folder (it need not exist yet). */
    private static Path realPlace(Path file) {
        Path absolute = file.toAbsolutePath().normalize();
        try {
            return Files.exists(absolute) ? absolute.toRealPath() : absolute.getParent().toRealPath().resolve(absolute.getFileName());
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

    /** Whether {@code file} is a regular file that starts as a PNG file does; false if it cannot be read (reading it will say why). */
    private static boolean isPngPicture(Path file) {
        byte[] signature = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
        if (!Files.isRegularFile(file)) {
            return false; // a FIFO or a device: reading ahead would take bytes the scene's reader needs
        }
        try (InputStream in = Files.newInputStream(file)) {
            return Arrays.equals(in.readNBytes(signature.length), signature);
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /** {@code scenes/a.txt} gives {@code scenes/a.png}; a name without extension gets {@code .png}. */
    static Path defaultOutput(Path scene) {
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = dot > 0 ? name.substring(0, dot) : name;
        return scene.resolveSibling(base + ".png");
    }
}
