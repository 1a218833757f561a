package rtd.pov;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;

/** Runs POV-Ray for the tests, where it is installed; elsewhere the tests that need it are skipped. */
final class PovRay {

    private PovRay() {
    }

    /** Skips the calling test, saying how to install POV-Ray, unless {@code povray} runs. */
    static void assumeInstalled() {
        assumeTrue(installed(), "POV-Ray is not installed, so rtd is not checked against it; install it with "
                + "'apt-get install povray' (Debian, Ubuntu) or 'brew install povray' (macOS) and run the tests again");
    }

    private static boolean installed() {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, "povray"))) {
                return true;
            }
        }
        return false;
    }

    /** Renders {@code pov} (a file in {@code dir}) at {@code w × h} with the command its comment gives, and reads the picture. */
    static BufferedImage render(Path dir, String pov, int w, int h) throws IOException, InterruptedException {
        String png = pov.replace(".pov", "-pov.png");
        List<String> command = List.of(PovScene.command(pov, png, w, h).split(" "));
        Process process = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("povray.log").toFile()).start();
        if (!process.waitFor(5, TimeUnit.MINUTES) || process.exitValue() != 0) {
            process.destroyForcibly();
            throw new IOException("povray failed: " + Files.readString(dir.resolve("povray.log")));
        }
        return ImageIO.read(dir.resolve(png).toFile());
    }
}
