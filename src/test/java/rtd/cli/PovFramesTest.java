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
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/**
 * {@code --export-pov} with {@code --frames}: one POV-Ray file whose numbers follow POV-Ray's clock, or whose
 * frames are written one by one where a number cannot be, and the options that render rtd's frames; frames that
 * POV-Ray renders from it are compared with rtd's.
 */
@DisplayName("--export-pov of an animation")
class PovFramesTest {

    private static final int W = 160;
    private static final int H = 90;
    private static final int FRAMES = 5;
    /** A box that a transformation turns with the clock: a number the export does not write with POV-Ray's clock. */
    private static final String SPINNING_BOX = """
            ambient:(30|30|60)
            perspective_camera:(0|4|10):(at 0|0|0):(50)
            transform:(spin):(rotate_y 360*clock)
            box:(-1|-1|-1):(1|1|1):(255|120|0):(spin)
            sphere:(3*clock|2|0):(0.5):(0|200|255)
            """;

    /** Every shape the clock can move, the orthographic camera, a light and the background, each following the clock. */
    private static final String EVERY_SHAPE_ON_THE_CLOCK = """
            let:(t):(360*clock)
            ambient:(20|30|40+100*clock)
            orthographic_camera:(2*sin(t)|3|10):(at 0|0|0):(20 + 10*clock)
            light:(-5 + 10*clock|8|6):(255|255*(1-clock/2)|200)
            plane:(0|-2 + clock|0):(0.2*sin(t)|1|0):(120|120|120)
            sphere:(-3 + 2*clock|0|0):(0.5 + 0.5*clock):(255*clock|100|50)
            box:(1|0 - clock|-1):(2.2 - 2*clock|1|0):(40|200|40)
            triangle:(-2|2|0):(0|2 + clock|0):(-1|3|-clock):(200|200|0)
            cylinder:(2|-1|1):(2|1 + clock|1):(0.3 + 0.2*clock):(0|0|255)
            cone:(-1|-1|2):(0.5*clock):(-1|1|2):(0.6):(255|0|255)
            """;

    @TempDir
    Path dir;

    /** Exports {@code scene} (a path) as an animation of {@code frames} frames named after {@code name}, and draws rtd's frames. */
    private Run export(String scene, String name, int frames, int w, int h) {
        return Cli.run(scene, "--frames", "" + frames, "--width", "" + w, "--height", "" + h, "-o",
                dir.resolve(name + ".png").toString(), "--export-pov", dir.resolve(name + ".pov").toString());
    }

    private String example(String name) {
        return Path.of("examples", name + ".txt").toString();
    }

    @Test
    void givesThePovrayOptionsForTheSameFrames() throws IOException {
        Run run = export(example("orbit"), "orbit", 3, 64, 36);
        assertThat(run.exitCode()).as(run.err()).isZero();
        String pov = Files.readString(dir.resolve("orbit.pov"));
        assertThat(pov.lines().limit(2)).anySatisfy(line -> assertThat(line).contains("+W64 +H36", "+KFI0 +KFF2 +KI0 +KF1"));
        assertThat(run.err()).contains("render its 3 frames with POV-Ray");
    }

    @ParameterizedTest
    @ValueSource(strings = {"orbit", "bouncing_ball", "planets"})
    void writesTheClockOfAnExampleAsPovRaysClockInOneScene(String name) throws IOException {
        Run run = export(example(name), name, 3, 64, 36);
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(Files.readString(dir.resolve(name + ".pov"))).contains("clock").doesNotContain("#switch", "#case");
    }

    /**
     * Frame 0 and frame 2 of 5 (clock 0.5): POV-Ray's picture is rtd's but for the odd pixel on an edge (the
     * orbit, flat: at most 0.25 % of the pixels differ at all, where a camera without its half-pixel shift makes
     * 0.6 % differ) or of a shadow (the ball, shaded: at most 1 % differ by more than 8 levels, as for a still
     * scene).
     */
    @ParameterizedTest
    @CsvSource({"orbit, 0, 0", "orbit, 2, 0", "bouncing_ball, 0, 8", "bouncing_ball, 2, 8"})
    void aFrameRenderedByPovRayFromTheClockMatchesRtdsFrame(String name, int frame, int levels) throws Exception {
        assumePovRay();
        Run run = export(example(name), name, FRAMES, W, H);
        assertThat(run.exitCode()).as(run.err()).isZero();
        int limit = levels == 0 ? W * H / 400 : W * H / 100;
        assertThat(differing(povRay(name, frame), rtd(name, frame), levels)).as("pixels that differ, of " + W * H)
                .isLessThanOrEqualTo(limit);
    }

    @Test
    void aSceneWithANumberThatCannotFollowPovRaysClockIsWrittenFrameByFrame() throws Exception {
        Files.writeString(dir.resolve("spin.txt"), SPINNING_BOX);
        Run run = export(dir.resolve("spin.txt").toString(), "spin", FRAMES, W, H);
        assertThat(run.exitCode()).as(run.err()).isZero();
        String pov = Files.readString(dir.resolve("spin.pov"));
        assertThat(pov).contains("the numbers that use rtd's clock in the 'transform' at line 3.", "#switch (frame_number)",
                "#case (0)", "#case (4)").doesNotContain("#case (5)");
        assertThat(pov.split("#version 3.7;", -1)).as("one #version, before the frames").hasSize(2);
        assertThat(pov).doesNotContain("Render it at rtd's size");
        assumePovRay();
        assertThat(differing(povRay("spin", 1), rtd("spin", 1), 8)).as("pixels that differ, of " + W * H)
                .isLessThanOrEqualTo(W * H / 100);
    }

    /**
     * Frame 2 of 5 of a scene whose every kind of number follows the clock, rendered by POV-Ray, is POV-Ray's
     * picture of the still export at clock 0.5, but for the odd pixel on an edge (POV-Ray works out in double what
     * rtd rounds to float): at most 1 % of the pixels differ by more than 8 levels (0.3 % do).
     */
    @Test
    void everyShapeLightAndCameraFollowingTheClockDrawsTheStillAtThatClock() throws Exception {
        assumePovRay();
        Files.writeString(dir.resolve("every.txt"), EVERY_SHAPE_ON_THE_CLOCK);
        Run run = export(dir.resolve("every.txt").toString(), "every", FRAMES, W, H);
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(Files.readString(dir.resolve("every.pov"))).doesNotContain("#switch");
        Run still = Cli.run(dir.resolve("every.txt").toString(), "--clock", "0.5", "--width", "" + W, "--height", "" + H,
                "-o", dir.resolve("still.png").toString(), "--export-pov", dir.resolve("still.pov").toString());
        assertThat(still.exitCode()).as(still.err()).isZero();
        BufferedImage stillPov = render(List.of("povray", "+Istill.pov", "+Ostill-pov.png", "+W" + W, "+H" + H, "+FN", "-A",
                "-D", "File_Gamma=1.0"), "still-pov.png");
        assertThat(differing(povRay("every", 2), stillPov, 8)).as("pixels that differ, of " + W * H)
                .isLessThanOrEqualTo(W * H / 100);
    }

    /** At {@code --scale 0.5} the orthographic camera's zoom is halved, as rtd halves it; one that follows the clock is written frame by frame. */
    @Test
    void anOrthographicSceneAtAScaleFollowsTheClockWithItsZoomScaled() throws Exception {
        Files.writeString(dir.resolve("slide.txt"), "ambient:(0|0|40)\northographic_camera:(0|0|10):(0|0|-1):(40)\n"
                + "sphere:(2*clock - 1|0|0):(1):(255|0|0)\n");
        Run run = Cli.run(dir.resolve("slide.txt").toString(), "--frames", "" + FRAMES, "--width", "" + 2 * W, "--height",
                "" + 2 * H, "--scale", "0.5", "-o", dir.resolve("slide.png").toString(), "--export-pov",
                dir.resolve("slide.pov").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(Files.readString(dir.resolve("slide.pov"))).contains("right <8, 0, 0>").doesNotContain("#switch");
        Files.writeString(dir.resolve("zoom.txt"), "orthographic_camera:(0|0|10):(0|0|-1):(40 + clock)\n");
        Run zoom = Cli.run(dir.resolve("zoom.txt").toString(), "--frames", "3", "--width", "64", "--height", "36", "--scale",
                "0.5", "-o",
                dir.resolve("zoom.png").toString(), "--export-pov", dir.resolve("zoom.pov").toString());
        assertThat(zoom.exitCode()).as(zoom.err()).isZero();
        assertThat(Files.readString(dir.resolve("zoom.pov"))).contains("the orthographic camera at --scale", "#switch");
        assumePovRay();
        assertThat(differing(povRay("slide", 2), rtd("slide", 2), 0)).as("pixels that differ, of " + W * H)
                .isLessThanOrEqualTo(W * H / 400);
    }

    @Test
    void aSceneThatDoesNotUseTheClockIsWrittenOnce() throws IOException {
        Run run = export(example("glass_and_mirror"), "still", 3, 64, 36);
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(Files.readString(dir.resolve("still.pov"))).contains("does not use the clock").doesNotContain("#switch");
    }

    /** Frame {@code frame} of the exported {@code name}.pov, rendered by POV-Ray with the clock options the file gives. */
    private BufferedImage povRay(String name, int frame) throws IOException, InterruptedException {
        return render(List.of("povray", "+I" + name + ".pov", "+O" + name + "-pov.png", "+W" + W, "+H" + H, "+FN", "-A", "-D",
                "File_Gamma=1.0", "+KFI0", "+KFF" + (FRAMES - 1), "+KI0", "+KF1", "+SF" + frame, "+EF" + frame),
                name + "-pov" + frame + ".png");
    }

    /** Runs POV-Ray's {@code command} in the folder and reads the picture it wrote, {@code png}. */
    private BufferedImage render(List<String> command, String png) throws IOException, InterruptedException {
        Process process = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("povray.log").toFile()).start();
        assertThat(process.waitFor(2, TimeUnit.MINUTES) && process.exitValue() == 0)
                .as(Files.readString(dir.resolve("povray.log"))).isTrue();
        return ImageIO.read(dir.resolve(png).toFile());
    }

    private BufferedImage rtd(String name, int frame) throws IOException {
        return ImageIO.read(dir.resolve(name + "-00" + frame + ".png").toFile());
    }

    /** How many pixels differ by more than {@code levels} in some channel. */
    private static int differing(BufferedImage a, BufferedImage b, int levels) {
        int differing = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int p = a.getRGB(x, y);
                int q = b.getRGB(x, y);
                int most = 0;
                for (int shift = 0; shift < 24; shift += 8) {
                    most = Math.max(most, Math.abs((p >> shift & 0xFF) - (q >> shift & 0xFF)));
                }
                differing += most > levels ? 1 : 0;
            }
        }
        return differing;
    }

    private static void assumePovRay() {
        assumeTrue(onPath("povray"), "POV-Ray is not installed (apt-get install povray): the frames are not compared");
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
