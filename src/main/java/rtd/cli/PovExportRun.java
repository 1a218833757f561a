package rtd.cli;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Locale;
import java.util.concurrent.ThreadLocalRandom;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import rtd.pov.PovScene;
import rtd.scene.Scene;

/**
 * {@code --export-pov FILE.pov}: writes the scene for POV-Ray ({@link PovScene}) and says how to render it. Where
 * it goes is decided before the scene is read, by the rules of {@code -o} ({@link OutputTarget}), and only to a
 * name ending in {@code .pov}, also behind a link, so that a slip cannot replace a mesh, a scene or a picture.
 */
final class PovExportRun {

    private PovExportRun() {
    }

    /** Where the export of {@code file} goes; a name or place that may not be written is a misuse or a {@link FileError}. */
    static OutputTarget plan(Path file, Path scene, CommandLine commandLine) throws FileError {
        if (file.toString().equals("-")) {
            throw new ParameterException(commandLine, "--export-pov writes a file, not standard output ('-'); give a "
                    + "name that ends in .pov, such as scene.pov");
        }
        if (file.getFileName() != null && file.getFileName().toString().indexOf('"') >= 0) { // the folder is cd's
            throw new ParameterException(commandLine, "--export-pov '" + file + "': a name with a double quote cannot "
                    + "be given to POV-Ray; choose one without");
        }
        if (!endsInPov(file)) {
            String name = file.getFileName() == null ? "" : file.getFileName().toString();
            String base = name.contains(".") ? name.substring(0, name.lastIndexOf('.')) : name;
            throw new ParameterException(commandLine, "--export-pov writes a POV-Ray scene, and its name must end in "
                    + ".pov; '" + file + "' does not: give a name such as " + (base.isEmpty() ? "scene" : base) + ".pov");
        }
        OutputTarget target = OutputTarget.of(file, scene, "--export-pov", commandLine);
        if (target.kind() == OutputTarget.Kind.REPLACE && !endsInPov(target.file())) {
            throw new ParameterException(commandLine, "'" + file + "' leads to '" + target.file() + "', whose name does "
                    + "not end in .pov; --export-pov replaces only a POV-Ray scene");
        }
        return target;
    }

    private static boolean endsInPov(Path file) {
        return file.getFileName() != null && file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".pov");
    }

    /** Writes the export of {@code scene} at {@code width × height}, and answers the lines that say how to render it. */
    static String write(Scene scene, OutputTarget target, int width, int height) throws FileError {
        Path file = target.spelt();
        String name = file.getFileName().toString();
        String text;
        try {
            text = PovScene.of(scene, width, height, name);
        } catch (IllegalArgumentException e) {
            throw new FileError("cannot export to POV-Ray: " + e.getMessage());
        }
        try {
            if (target.kind() == OutputTarget.Kind.STREAM) {
                try (OutputStream out = Files.newOutputStream(target.file(), StandardOpenOption.WRITE)) {
                    out.write(text.getBytes(StandardCharsets.UTF_8));
                }
            } else {
                replace(target.file(), text);
            }
        } catch (IOException e) {
            throw new FileError("cannot write '" + file + "'", e);
        }
        String png = name.replaceAll("(?i)\\.pov$", "") + "-pov.png";
        return "rtd: wrote " + file + "; render it with POV-Ray (apt-get install povray):\n"
                + "  cd " + PovScene.shellWord(file.toAbsolutePath().getParent().toString()) + " && "
                + PovScene.command(name, png, width, height);
    }

    /** Writes {@code text} to a temporary file beside {@code file}, then moves it into place: never half a file. */
    private static void replace(Path file, String text) throws IOException {
        // Not Files.createTempFile: its file may be read by its owner only, and would stay so.
        Path temporary = file.toAbsolutePath().getParent().resolve("." + file.getFileName() + "."
                + Long.toHexString(ThreadLocalRandom.current().nextLong()) + ".tmp");
        try {
            Files.writeString(temporary, text, StandardCharsets.UTF_8, StandardOpenOption.CREATE_NEW,
                    StandardOpenOption.WRITE);
            Files.move(temporary, file, StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }
}
