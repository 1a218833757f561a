package rtd.cli;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
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
 * {@code --export-pov FILE.pov}: writes the scene for POV-Ray ({@link PovScene}) and says how to
 * render it. Where it goes is decided before the scene is read, by the rules of {@code -o}
 * ({@link OutputTarget}): never a folder, the scene file, or a link's own file; and only a name
 * that ends in {@code .pov}, so that a slip cannot replace a mesh, a scene or a picture.
 */
final class PovExportRun {

    private PovExportRun() {
    }

    /**
     * Where the export of {@code file} goes; a name or place that may not be written is a
     * mistake on the command line (thrown) or a {@link FileError}.
     */
    static OutputTarget plan(Path file, Path scene, CommandLine commandLine) throws FileError {
        String name = file.getFileName() == null ? "" : file.getFileName().toString();
        if (!name.toLowerCase(Locale.ROOT).endsWith(".pov")) {
            String base = name.contains(".") ? name.substring(0, name.lastIndexOf('.')) : name;
            throw new ParameterException(commandLine, "--export-pov writes a POV-Ray scene, and its name must end in "
                    + ".pov; '" + file + "' does not: give a name such as " + (base.isEmpty() ? "scene" : base) + ".pov");
        }
        OutputTarget target;
        try {
            target = OutputTarget.of(file, scene, "--export-pov");
        } catch (OutputTarget.Refusal refusal) {
            if (refusal.misuse()) {
                throw new ParameterException(commandLine, refusal.getMessage());
            }
            throw new FileError(refusal.getMessage(), null);
        }
        if (target.folder().isPresent()) {
            JobPlanner.checkFolder(file, target.folder().get());
        }
        return target;
    }

    /** Writes the export to {@code target}; false after saying on {@code err} why it could not be written. */
    static boolean write(Scene scene, OutputTarget target, RenderSettings settings, PrintWriter err) {
        Path file = target.spelt();
        String name = file.getFileName().toString();
        String text;
        try {
            text = PovScene.of(scene, settings.width(), settings.height(), name);
        } catch (IllegalArgumentException e) {
            err.println("rtd: cannot export to POV-Ray: " + e.getMessage());
            return false;
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
            err.println("rtd: cannot write '" + file + "': " + FileProblems.reason(e));
            return false;
        }
        String png = name.replaceAll("(?i)\\.pov$", "") + "-pov.png";
        err.println("rtd: wrote " + file + "; render it with POV-Ray (apt-get install povray):");
        err.println("  cd " + (file.toAbsolutePath().getParent()) + " && " + PovScene.command(name, png, settings.width(),
                settings.height()));
        err.flush();
        return true;
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
