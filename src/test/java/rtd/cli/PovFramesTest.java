package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** {@code --export-pov} with {@code --frames}: one POV-Ray file whose frames are rtd's, and the options that render them. */
@DisplayName("--export-pov of an animation")
class PovFramesTest {

    private static final Path ORBIT = Path.of("examples", "orbit.txt");

    @TempDir
    Path dir;

    private Run export(int frames) {
        return Cli.run(ORBIT.toString(), "--frames", "" + frames, "--width", "64", "--height", "36", "-o",
                dir.resolve("orbit.png").toString(), "--export-pov", dir.resolve("orbit.pov").toString());
    }

    @Test
    void givesThePovrayOptionsForTheSameFramesAndWritesTheClockAsPovRaysClock() throws IOException {
        Run run = export(3);
        assertThat(run.exitCode()).as(run.err()).isZero();
        String pov = Files.readString(dir.resolve("orbit.pov"));
        assertThat(pov.lines().limit(2)).anySatisfy(line -> assertThat(line).contains("+W64 +H36", "+KFI0 +KFF2 +KI0 +KF1"));
        assertThat(pov).contains("clock").doesNotContain("#switch", "#case");
        assertThat(run.err()).contains("render its 3 frames with POV-Ray");
    }

    /** Frame 1 of 3 (clock 0.5, the camera on the far side): POV-Ray's picture is rtd's but for the odd edge pixel. */
    @Test
    void aFrameRenderedByPovRayMatchesRtdsFrame() throws IOException, InterruptedException {
        assumeTrue(onPath("povray"), "POV-Ray is not installed (apt-get install povray): the frame is not compared");
        assertThat(export(3).exitCode()).isZero();
        List<String> command = List.of("povray", "+Iorbit.pov", "+Oorbit-pov.png", "+W64", "+H36", "+FN", "-A", "-D",
                "File_Gamma=1.0", "+KFI0", "+KFF2", "+KI0", "+KF1", "+SF1", "+EF1");
        Process process = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("povray.log").toFile()).start();
        assertThat(process.waitFor(2, TimeUnit.MINUTES) && process.exitValue() == 0)
                .as(Files.readString(dir.resolve("povray.log"))).isTrue();
        BufferedImage pov = ImageIO.read(new File(dir.resolve("orbit-pov1.png").toString()));
        BufferedImage rtd = ImageIO.read(new File(dir.resolve("orbit-001.png").toString()));
        int differing = 0;
        for (int y = 0; y < 36; y++) {
            for (int x = 0; x < 64; x++) {
                differing += (pov.getRGB(x, y) & 0xFFFFFF) != (rtd.getRGB(x, y) & 0xFFFFFF) ? 1 : 0;
            }
        }
        assertThat(differing).as("pixels that differ, of 2304").isLessThanOrEqualTo(2304 / 50);
    }

    private static boolean onPath(String program) {
        for (String folder : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (!folder.isEmpty() && Files.isExecutable(Path.of(folder, program))) {
                return true;
            }
        }
        return false;
    }
}
