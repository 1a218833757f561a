package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

@DisplayName("The teaching options on the command line")
class TeachingOptionsTest {

    private static final String EXAMPLE = Path.of("examples", "input_rtd.txt").toString();

    @TempDir
    Path dir;

    @Test
    void explainPrintsThePixelsStepsToStandardOutputAndWritesNoPicture() {
        Run run = Cli.run(EXAMPLE, "-o", dir.resolve("out.png").toString(), "--explain", "460,490");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.out()).contains("pixel (460, 490) of the 1920 × 1080 picture", "a = R·R = 1", "pixel colour: 255 0 0");
        assertThat(dir.resolve("out.png")).doesNotExist();
    }

    @Test
    void explainAgreesWithTheRenderedPicture() throws IOException {
        Path out = dir.resolve("out.png");
        assertThat(Cli.run(EXAMPLE, "-o", out.toString(), "--width", "96", "--height", "54").exitCode()).isZero();
        BufferedImage picture = ImageIO.read(out.toFile());
        for (int[] pixel : new int[][] {{0, 0}, {20, 27}, {60, 10}, {30, 30}, {95, 53}}) {
            Run run = Cli.run(EXAMPLE, "--width", "96", "--height", "54", "--explain", pixel[0] + "," + pixel[1]);
            int rgb = picture.getRGB(pixel[0], pixel[1]);
            assertThat(run.out()).contains("pixel colour: " + (rgb >> 16 & 0xFF) + " " + (rgb >> 8 & 0xFF) + " " + (rgb & 0xFF));
        }
    }

    @Test
    void aPixelOutsideTheImageOrAMalformedOneIsMisuseThatNamesTheImagesSize() {
        for (String pixel : List.of("1920,0", "0,1080", "99999999999,1", "-1,5", "3", "a,b", "1,2,3", "")) {
            Run run = Cli.run(EXAMPLE, "--explain", pixel);
            assertThat(run.exitCode()).as(pixel).isEqualTo(2);
            assertThat(run.err()).as(pixel).contains("--explain", "1920 × 1080", "Try 'java -jar rtd.jar --help'");
        }
        Run small = Cli.run(EXAMPLE, "--width", "30", "--height", "20", "--explain", "30,5");
        assertThat(small.err()).contains("0 ≤ X < 30 and 0 ≤ Y < 20 (the image is 30 × 20)");
    }

    @Test
    void viewCostWritesAHeatMapWithItsLegendAndPrintsTheScale() throws IOException {
        Path out = dir.resolve("cost.png");
        Run run = Cli.run(EXAMPLE, "-o", out.toString(), "--width", "96", "--height", "54", "--view", "cost", "--accel", "none");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("logarithmic scale from 0 (black) to 2", "2.00 per ray, at most 2");
        BufferedImage image = ImageIO.read(out.toFile());
        assertThat(image.getWidth()).isEqualTo(96);
        assertThat(image.getHeight()).isEqualTo(54 + 32);
    }

    @Test
    void statsWithAViewReportTheViewsPhasesAndItsWorkPerRay() {
        Path out = dir.resolve("cost.png");
        Run run = Cli.run(EXAMPLE, "-o", out.toString(), "--width", "96", "--height", "54", "--view", "cost",
                "--accel", "none", "--threads", "2", "--stats");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("parse ", "build ", "no BVH: the paper's loop tests every object",
                "5,184 rays on 2 threads", "write ", out.toString(), "per ray: 2.00 intersection tests");
        Run without = Cli.run(EXAMPLE, "-o", out.toString(), "--width", "96", "--height", "54", "--view", "cost");
        assertThat(without.err()).doesNotContain("per ray:");
    }

    @Test
    void explainWithPaperExplainsTheFlatPictureThatPaperDraws() throws IOException {
        String lit = Path.of("examples", "lit_paper.txt").toString();
        Path out = dir.resolve("paper.png");
        assertThat(Cli.run(lit, "--paper", "--scale", "0.25", "-o", out.toString()).exitCode()).isZero();
        int rgb = ImageIO.read(out.toFile()).getRGB(60, 130) & 0xFFFFFF;
        Run run = Cli.run(lit, "--paper", "--scale", "0.25", "--explain", "60,130");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(rgb).isEqualTo(0xFF0000);
        assertThat(run.out()).contains("the paper's flat colours", "pixel colour: 255 0 0").doesNotContain("WhittedShader");
        assertThat(run.err()).contains("--paper draws as the paper does, in flat colours");
        assertThat(Docs.errors()).contains(run.err().strip());
        Run shaded = Cli.run(lit, "--scale", "0.25", "--explain", "60,130");
        assertThat(shaded.out()).contains("WhittedShader.shade").doesNotContain("pixel colour: 255 0 0");
    }

    @Test
    void theScenesWarningsAreShownOnceWithExplainAndWithAView() throws IOException {
        Path scene = Files.writeString(dir.resolve("scene.txt"), "orthographic_camera:(0|0|20):(0|0|-1):(50)\n"
                + "light:(0|9|9):(255|255|255)\nmaterial:(unused):(diffuse=0.5)\nsphere:(0|0|0):(3):(255|0|0)\n");
        String warning = "scene.txt:3:11: warning: material 'unused' is defined, but no object names it";
        Run explain = Cli.run(scene.toString(), "--width", "64", "--height", "36", "--explain", "32,18");
        Run view = Cli.run(scene.toString(), "--width", "64", "--height", "36", "--view", "depth", "-o",
                dir.resolve("v.png").toString());
        for (Run run : List.of(explain, view)) {
            assertThat(run.exitCode()).as(run.err()).isZero();
            assertThat(run.err().split(java.util.regex.Pattern.quote(warning), -1)).hasSize(2);
        }
    }

    @Test
    void statsWithExplainAreNotUsedAndSaySo() {
        Run run = Cli.run(EXAMPLE, "--explain", "460,490", "--stats");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("--explain follows one ray and times nothing; --stats is not used");
        assertThat(Docs.errors()).contains(run.err().strip());
        assertThat(run.out()).contains("pixel colour: 255 0 0");
    }

    @Test
    void aViewWithoutOutputGoesBesideTheSceneUnderTheViewsName() throws IOException {
        Path scene = Files.copy(Path.of(EXAMPLE), dir.resolve("paper.txt"));
        for (String view : List.of("cost", "depth", "normal", "id")) {
            Run run = Cli.run(scene.toString(), "--width", "48", "--height", "27", "--view", view);
            assertThat(run.exitCode()).as(run.err()).isZero();
            assertThat(dir.resolve("paper-" + view + ".png")).isRegularFile();
        }
        assertThat(dir.resolve("paper.png")).doesNotExist();
    }

    @Test
    void aViewIsWrittenInTheFormatOfItsOutputsExtensionAsAPictureIs() throws IOException {
        Path jpeg = dir.resolve("depth.jpg");
        Run run = Cli.run(EXAMPLE, "-o", jpeg.toString(), "--width", "48", "--height", "27", "--view", "depth");
        assertThat(run.exitCode()).as(run.err()).isZero();
        byte[] bytes = Files.readAllBytes(jpeg);
        assertThat(new int[] {bytes[0] & 0xFF, bytes[1] & 0xFF}).containsExactly(0xFF, 0xD8); // a JPEG's start
        assertThat(ImageIO.read(jpeg.toFile()).getWidth()).isEqualTo(48);

        Path unknown = dir.resolve("depth.xyz");
        Run refused = Cli.run(EXAMPLE, "-o", unknown.toString(), "--view", "depth");
        assertThat(refused.exitCode()).isEqualTo(2);
        assertThat(refused.err()).contains("'.xyz', a format rtd cannot write", ".png");
        assertThat(unknown).doesNotExist();
    }

    @Test
    void aViewToStandardOutputIsMisuseAndWritesNoFileNamedDash() {
        Run run = Cli.run(EXAMPLE, "--view", "depth", "-o", "-");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("--view writes its picture to a file", "input_rtd-depth.png");
        assertThat(Path.of("-")).doesNotExist();
    }

    @Test
    void anUnknownViewIsMisuse() {
        Run run = Cli.run(EXAMPLE, "--view", "heat");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("--view", "cost, depth, normal, id");
    }

    @Test
    void watchRendersWithTheSameArgumentsLessWatch() {
        assertThat(SceneWatcher.withoutWatch(List.of("a.txt", "--watch", "-o", "b.png"))).containsExactly("a.txt", "-o", "b.png");
    }

    @Test
    void theTeachingOptionsSeeTheSameScaledPictureAsTheRender() throws IOException {
        Path out = dir.resolve("thumb.png");
        assertThat(Cli.run(EXAMPLE, "-o", out.toString(), "--scale", "0.25").exitCode()).isZero();
        BufferedImage picture = ImageIO.read(out.toFile());
        assertThat(picture.getWidth()).isEqualTo(480);
        int rgb = picture.getRGB(115, 122);
        assertThat(rgb & 0xFFFFFF).as("the red sphere in the thumbnail").isEqualTo(0xFF0000);
        Run run = Cli.run(EXAMPLE, "--scale", "0.25", "--explain", "115,122");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.out()).contains("of the 480 × 270 picture", "pixel colour: 255 0 0");
        Path view = dir.resolve("view.png");
        assertThat(Cli.run(EXAMPLE, "--scale", "0.25", "--view", "id", "-o", view.toString()).exitCode()).isZero();
        assertThat(ImageIO.read(view.toFile()).getWidth()).isEqualTo(480);
    }

    @Test
    void theTeachingOptionsRefuseSeveralScenesAndStandardInput() {
        Run several = Cli.run(EXAMPLE, EXAMPLE, "--view", "id");
        assertThat(several.exitCode()).isEqualTo(2);
        assertThat(several.err()).contains("--view works on one scene file, but 2 were given");
        Run stdin = Cli.run("-", "--explain", "1,1");
        assertThat(stdin.exitCode()).isEqualTo(2);
        assertThat(stdin.err()).contains("--explain needs a scene file; it cannot work on standard input");
        Run watch = Cli.run(EXAMPLE, EXAMPLE, "--watch");
        assertThat(watch.exitCode()).isEqualTo(2);
        assertThat(watch.err()).contains("--watch works on one scene file");
        Run watchToPipe = Cli.run(EXAMPLE, "--watch", "-o", "-");
        assertThat(watchToPipe.exitCode()).isEqualTo(2);
        assertThat(watchToPipe.err()).startsWith("rtd: --watch writes the picture again at each save, which cannot go to "
                + "standard output ('-o -'); give a file, such as -o out.png");
    }

    @Test
    @DisplayName("--explain 300 400, the pixel written without its comma, is asked whether it meant --explain 300,400")
    void aPixelWithoutItsCommaIsAskedForIt() {
        for (String[] args : new String[][] {{"--explain", "300", "400", EXAMPLE}, {EXAMPLE, "--explain", "300", "400"},
            {"--explain", "300", "400"}}) {
            Run run = Cli.run(args);
            assertThat(run.exitCode()).isEqualTo(2);
            String message = run.err().lines().findFirst().orElse("");
            assertThat(message).isEqualTo("rtd: --explain takes the pixel as X,Y with a comma, and '400' was read as "
                    + "a scene file; did you mean --explain 300,400?");
            assertThat(Docs.errors()).contains(message);
        }
    }
}
