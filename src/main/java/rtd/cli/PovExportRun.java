package rtd.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ThreadLocalRandom;
import rtd.pov.PovScene;
import rtd.scene.Scene;

/** {@code --export-pov FILE.pov}: writes the scene for POV-Ray ({@link PovScene}) and says how to render it. */
final class PovExportRun {

    private PovExportRun() {
    }

    /** Writes the export; false after saying on {@code err} why it could not be written. */
    static boolean write(Scene scene, Path file, RenderSettings settings, PrintWriter err) {
        String name = file.getFileName() == null ? "scene.pov" : file.getFileName().toString();
        if (isSameFile(file, settings.scene())) {
            err.println("rtd: cannot write '" + file + "': it is the scene file itself; choose another name for --export-pov");
            return false;
        }
        String text;
        try {
            text = PovScene.of(scene, settings.width(), settings.height(), name);
        } catch (IllegalArgumentException e) {
            err.println("rtd: cannot export to POV-Ray: " + e.getMessage());
            return false;
        }
        try {
            Path folder = file.toAbsolutePath().getParent();
            // Not Files.createTempFile: its file may be read by its owner only, and would stay so.
            Path temporary = folder.resolve("." + name + "." + Long.toHexString(ThreadLocalRandom.current().nextLong())
                    + ".tmp");
            try {
                Files.writeString(temporary, text, StandardCharsets.UTF_8, StandardOpenOption.CREATE_NEW,
                        StandardOpenOption.WRITE);
                Files.move(temporary, file, StandardCopyOption.REPLACE_EXISTING);
            } finally {
                Files.deleteIfExists(temporary);
            }
        } catch (IOException e) {
            err.println("rtd: cannot write '" + file + "': " + FileProblems.reason(e));
            return false;
        }
        String png = name.replaceAll("\\.pov$", "") + "-pov.png";
        err.println("rtd: wrote " + file + "; render it with POV-Ray (apt-get install povray):");
        err.println("  cd " + (file.toAbsolutePath().getParent()) + " && " + PovScene.command(name, png, settings.width(),
                settings.height()));
        err.flush();
        return true;
    }

    private static boolean isSameFile(Path a, Path b) {
        try {
            return Files.exists(a) && Files.exists(b) && Files.isSameFile(a, b);
        } catch (IOException e) {
            return false;
        }
    }
}
