package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

@DisplayName("The command line")
class CommandLineTest {

    private static final Path EXAMPLE = Path.of("examples", "input_rtd.txt");

    @TempDir
    Path dir;

    private Path copyOfExample() throws IOException {
        return Files.copy(EXAMPLE, dir.resolve("input_rtd.txt"));
    }

    @Test
    void rendersTheExampleAt1920x1080AndExitsWith0() throws IOException {
        Path out = dir.resolve("out.png");
        Run run = Cli.run(EXAMPLE.toString(), "-o", out.toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        BufferedImage image = ImageIO.read(out.toFile());
        assertThat(image.getWidth()).isEqualTo(1920);
        assertThat(image.getHeight()).isEqualTo(1080);
        assertThat(image.getRGB(460, 490) & 0xFFFFFF).isEqualTo(0xFF0000);
    }

    @Test
    void withoutOutputOptionWritesTheScenesNameWithPngBesideIt() throws IOException {
        Path scene = copyOfExample();
        Run run = Cli.run(scene.toString(), "--width", "64", "--height", "36");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(dir.resolve("input_rtd.png")).isRegularFile();
    }

    @Test
    void theDefaultOutputNameReplacesOnlyTheLastExtension() {
        assertThat(JobPlanner.defaultOutput(Path.of("a/b.c.txt"), "")).isEqualTo(Path.of("a/b.c.png"));
        assertThat(JobPlanner.defaultOutput(Path.of("scene"), "")).isEqualTo(Path.of("scene.png"));
        assertThat(JobPlanner.defaultOutput(Path.of(".hidden"), "")).isEqualTo(Path.of(".hidden.png"));
    }

    @Test
    void widthAndHeightSetTheImageSize() throws IOException {
        Path out = dir.resolve("small.png");
        Run run = Cli.run(EXAMPLE.toString(), "-o", out.toString(), "--width", "320", "--height", "200");
        assertThat(run.exitCode()).isZero();
        BufferedImage image = ImageIO.read(out.toFile());
        assertThat(image.getWidth()).isEqualTo(320);
        assertThat(image.getHeight()).isEqualTo(200);
    }

    @Test
    void aWidthThatIsNotAPositiveWholeNumberIsMisuseWithExitCode2() {
        for (String width : new String[] {"0", "-5", "abc", "1.5"}) {
            Run run = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("x.png").toString(), "--width", width);
            assertThat(run.exitCode()).isEqualTo(2);
            assertThat(run.err()).contains("--width").contains("'" + width + "' is not a positive whole number")
                    .contains("Try 'java -jar rtd.jar --help'").doesNotContain("at rtd.");
        }
        assertThat(dir.resolve("x.png")).doesNotExist();
    }

    @Test
    void anUnknownOptionIsMisuseAndPicocliSuggestsTheNearestOne() {
        Run run = Cli.run(EXAMPLE.toString(), "--widht", "100");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("Unknown option: '--widht'").contains("Possible solutions: --width");
    }

    @Test
    void anOptionWithTwoLettersSwappedIsToldTheOptionItMeantFirst() {
        assertThat(Cli.run(EXAMPLE.toString(), "--wdith", "100").err())
                .contains("Unknown option: '--wdith'\nPossible solutions: --width\n");
        assertThat(Cli.run(EXAMPLE.toString(), "--sacle", "2").err()).contains("Possible solutions: --scale, --samples");
        assertThat(Cli.run(EXAMPLE.toString(), "--colr", "2").err()).doesNotContain("Possible solutions");
    }

    @Test
    void noSceneIsMisuse() {
        Run run = Cli.run();
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("Missing required parameter: 'SCENE'");
    }

    @Test
    void aMissingSceneFileIsAFileErrorWithExitCode1AndNoOutput() {
        Path out = dir.resolve("out.png");
        Run run = Cli.run(dir.resolve("nope.txt").toString(), "-o", out.toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("rtd: cannot read the scene file '" + dir.resolve("nope.txt") + "': no such file")
                .doesNotContain("Exception");
        assertThat(out).doesNotExist();
    }

    @Test
    void aSceneErrorNamesFileLineAndColumnWithExitCode1() throws IOException {
        Path scene = Files.writeString(dir.resolve("bad.txt"), "orthographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(1|2|3):(-1):(0|0|0)\n");
        Run run = Cli.run(scene.toString(), "-o", dir.resolve("out.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains(scene + ":2:17: error: the radius must be greater than 0, found -1");
        assertThat(dir.resolve("out.png")).doesNotExist();
    }

    @Test
    void versionAndHelpExitWith0() {
        Run version = Cli.run("--version");
        assertThat(version.exitCode()).isZero();
        assertThat(version.out()).startsWith("rtd ");
        Run help = Cli.run("--help");
        assertThat(help.exitCode()).isZero();
        assertThat(help.out()).contains("--width").contains("--height").contains("Exit codes:")
                .contains("2   the command line is wrong");
    }

    @Test
    void hIsNotTheHeight() {
        Run run = Cli.run(EXAMPLE.toString(), "-h");
        assertThat(run.exitCode()).isZero();
        assertThat(run.out()).contains("Usage: java -jar rtd.jar");
    }

    @Test
    void aFailedRunLeavesAnExistingOutputFileByteForByteAsItWas() throws IOException {
        Path out = Files.write(dir.resolve("out.png"), new byte[] {1, 2, 3, 4});
        Path scene = Files.writeString(dir.resolve("bad.txt"), "sphere:(1|2|3):(1):(0|0|0)\n");
        assertThat(Cli.run(scene.toString(), "-o", out.toString()).exitCode()).isEqualTo(1);
        assertThat(Files.readAllBytes(out)).containsExactly(1, 2, 3, 4);
        assertThat(Cli.run(EXAMPLE.toString(), "-o", out.toString(), "--width", "-1").exitCode()).isEqualTo(2);
        assertThat(Files.readAllBytes(out)).containsExactly(1, 2, 3, 4);
        try (var files = Files.list(dir)) {
            assertThat(files.map(p -> p.getFileName().toString())).containsExactlyInAnyOrder("out.png", "bad.txt");
        }
    }

    @Test
    void aFolderGivenAsTheSceneIsAFileError() {
        Run run = Cli.run(dir.toString(), "-o", dir.resolve("out.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).isEqualTo("rtd: cannot read the scene file '" + dir + "': it is a folder, not a file\n");
    }

    @Test
    void filesThatMayNotBeReadOrWrittenAreSaidToBeSo() {
        // The tests run as root here, which may read and write anything, so the words are checked
        // on the exceptions Java throws for such files.
        assertThat(FileError.reason(new java.nio.file.AccessDeniedException("secret.txt"))).isEqualTo("permission denied");
        assertThat(FileError.reason(new java.nio.file.NoSuchFileException("nope.txt"))).isEqualTo("no such file");
        assertThat(FileError.reason(new java.nio.file.FileSystemException("out.png", null, "No space left on device")))
                .isEqualTo("no space left on device");
    }

    @Test
    void aMissingOutputFolderIsAFileErrorBeforeAnyRendering() {
        Run run = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("no/such/folder/out.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("cannot write").contains("folder").contains("does not exist");
    }

    @Test
    void anOutputThatIsAFolderOrTheSceneItselfIsMisuse() throws IOException {
        assertThat(Cli.run(EXAMPLE.toString(), "-o", dir.toString()).exitCode()).isEqualTo(2);
        Path scene = Files.copy(EXAMPLE, dir.resolve("scene.png"));
        Run run = Cli.run(scene.toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("is the scene file itself");
        assertThat(Files.readString(scene)).isEqualTo(Files.readString(EXAMPLE));
    }

    @Test
    void anImageTooLargeForMemoryIsRefusedBeforeAllocating() {
        Run run = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("huge.png").toString(), "--width", "2000000", "--height", "2000000");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("2000000×2000000").contains("at most");
        Run big = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("huge.png").toString(), "--width", "46000", "--height", "46000");
        assertThat(big.exitCode()).isEqualTo(2);
        // -Xmx advice only where the machine has that much memory
        assertThat(big.err()).contains("needs 19.7 GiB of memory").containsAnyOf("-Xmx", "this machine has");
    }

    @Test
    @DisplayName("An image beyond Java's limit is told the largest size of its shape that Java holds, and the --scale")
    void anImageBeyondJavasLimitIsToldTheLargestOfItsShape() {
        // 2,147,483,639 pixels at most: √(2,147,483,639 / 10^10) = 0.46341 of each side, 46340 × 46340 pixels
        Run run = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("huge.png").toString(), "--width", "100000",
                "--height", "100000");
        String message = run.err().lines().findFirst().orElse("");
        assertThat(message).isEqualTo("rtd: a 100000×100000 image has 10,000,000,000 pixels; Java images hold at most "
                + "2,147,483,639: the largest of that shape is 46340×46340, or keep the view with --scale 0.463");
        assertThat(Docs.errors()).contains(message);
        // 60000 × 40000 at --scale 2 is 120000 × 80000: √(2,147,483,639 / 9.6·10^9) = 0.472965 of each side, and
        // of the factor 2, so --scale 0.945 (three digits, rounded down)
        assertThat(Cli.run(EXAMPLE.toString(), "--width", "60000", "--height", "40000", "--scale", "2").err())
                .contains("a 120000×80000 image has 9,600,000,000 pixels").contains("the largest of that shape is "
                        + "56755×37837, or keep the view with --scale 0.945");
    }

    @Test
    void threadsAndAccelAreCheckedAndAnyChoiceGivesTheSamePicture() throws IOException {
        assertThat(Cli.run(EXAMPLE.toString(), "--threads", "0").exitCode()).isEqualTo(2);
        Run accel = Cli.run(EXAMPLE.toString(), "--accel", "fast");
        assertThat(accel.exitCode()).isEqualTo(2);
        assertThat(accel.err()).contains("expected one of [auto, none, bvh, grid]");
        byte[] reference = null;
        for (String[] choice : new String[][] {{"1", "none"}, {"64", "none"}, {"3", "bvh"}, {"2", "auto"}, {"2", "grid"},
                {"1", "grid"}}) {
            Path out = dir.resolve("t" + choice[0] + choice[1] + ".png");
            Run run = Cli.run(EXAMPLE.toString(), "-o", out.toString(), "--width", "96", "--height", "54",
                    "--threads", choice[0], "--accel", choice[1]);
            assertThat(run.exitCode()).as(run.err()).isZero();
            byte[] png = Files.readAllBytes(out);
            if (reference == null) {
                reference = png;
            }
            assertThat(png).as("--threads %s --accel %s", choice[0], choice[1]).isEqualTo(reference);
        }
    }

    @Test
    void noProgressLineReachesAnErrorStreamThatIsNoTerminal() {
        Run run = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("p.png").toString(), "--scale", "0.05");
        assertThat(run.exitCode()).isZero();
        assertThat(run.err()).isEmpty();
    }

    @Test
    void statsReportEachPhaseAndTheWorkPerRay() {
        Run run = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("s.png").toString(), "--stats", "--accel", "none",
                "--width", "100", "--height", "50");
        assertThat(run.exitCode()).isZero();
        assertThat(run.err()).contains("parse").contains("build").contains("render").contains("write")
                .contains("5,000 rays").contains("per ray: 2.00 intersection tests");
    }

    @Test
    void autoTakesTheViewGridForALargeSceneInFlatColoursAndDrawsWhatTheBvhDraws() throws IOException {
        StringBuilder text = new StringBuilder("orthographic_camera:(0|0|20):(0|0|-1):(50)\n");
        java.util.Random random = new java.util.Random(5);
        for (int i = 0; i < 1_000; i++) {
            text.append(String.format(java.util.Locale.ROOT, "sphere:(%.3f|%.3f|%.3f):(%.3f):(%d|%d|%d)%n",
                    random.nextFloat() * 4 - 2, random.nextFloat() * 2 - 1, random.nextFloat() * 4 - 2,
                    0.01 + random.nextFloat() * 0.05, i % 256, i / 256 % 256, 99));
        }
        Path many = Files.writeString(dir.resolve("many.txt"), text);
        Run auto = Cli.run(many.toString(), "-o", dir.resolve("auto.png").toString(), "--stats", "--width", "200",
                "--height", "100");
        assertThat(auto.exitCode()).as(auto.err()).isZero();
        assertThat(auto.err()).containsPattern("build .* view grid of [0-9,]+ cells of [0-9]+ × [0-9]+ pixels, [0-9,]+ "
                + "entries\n").doesNotContain("BVH");
        Run bvh = Cli.run(many.toString(), "-o", dir.resolve("bvh.png").toString(), "--stats", "--width", "200",
                "--height", "100", "--accel", "bvh");
        assertThat(bvh.err()).contains("BVH of").contains("BVH nodes visited");
        assertThat(Files.readAllBytes(dir.resolve("auto.png"))).isEqualTo(Files.readAllBytes(dir.resolve("bvh.png")));

        Path lit = Files.writeString(dir.resolve("lit.txt"), text + "light:(0|5|20):(255|255|255)\n");
        Run shaded = Cli.run(lit.toString(), "-o", dir.resolve("lit.png").toString(), "--stats", "--width", "20",
                "--height", "10");
        assertThat(shaded.exitCode()).as(shaded.err()).isZero();
        assertThat(shaded.err()).as("the camera's rays take the view grid, the shadow rays the light's, the others the BVH")
                .contains("view grid of").containsPattern(", 1 light grid of [0-9,]+ entries, and BVH of");
        java.util.regex.Matcher answered = java.util.regex.Pattern.compile("render .* ([0-9,]+) rays .*\n +([0-9,]+) "
                + "answered by the view grid, ([0-9,]+) by the light grids(, ([0-9,]+) by the BVH)?\n")
                .matcher(shaded.err());
        assertThat(answered.find()).as(shaded.err()).isTrue();
        long byTree = answered.group(5) == null ? 0 : number(answered.group(5)); // left out if it answered none
        assertThat(number(answered.group(2)) + number(answered.group(3)) + byTree)
                .as("every ray answered once").isEqualTo(number(answered.group(1)));
        assertThat(number(answered.group(2))).as("the camera's rays").isEqualTo(20 * 10);
        Run tree = Cli.run(lit.toString(), "-o", dir.resolve("lit-bvh.png").toString(), "--width", "20", "--height", "10",
                "--accel", "bvh");
        assertThat(tree.exitCode()).as(tree.err()).isZero();
        assertThat(Files.readAllBytes(dir.resolve("lit.png"))).isEqualTo(Files.readAllBytes(dir.resolve("lit-bvh.png")));
    }

    @Test
    void statsCountOneObjectAndOneNodeInTheSingularAndSayTheTotalLeavesOutTheJvmsStart() throws IOException {
        Path one = Files.writeString(dir.resolve("one.txt"), "orthographic_camera:(0|0|20):(0|0|-1):(50)\n"
                + "sphere:(0|0|0):(1):(255|0|0)\n");
        Run run = Cli.run(one.toString(), "-o", dir.resolve("one.png").toString(), "--stats", "--width", "64",
                "--height", "36", "--accel", "bvh");
        assertThat(run.exitCode()).isZero();
        assertThat(run.err()).contains(" 1 object\n").contains("BVH of 1 node\n")
                .containsPattern("total +[0-9.]+ s  from reading the scene to the written picture; the JVM's start is not "
                        + "counted\n");
    }

    @Test
    void theHelpAndItsMessagesNameTheCommandAsItIsTyped() {
        Run help = Cli.run("--help");
        assertThat(help.out()).startsWith("Usage: java -jar rtd.jar ").doesNotContainPattern("(?m)^\\s*rtd ")
                .contains("  java -jar rtd.jar examples/input_rtd.txt -o out.png");
        Run misuse = Cli.run("--widht", "3", "x.txt");
        assertThat(misuse.err()).endsWith("Try 'java -jar rtd.jar --help' for more information.\n");
        assertThat(Docs.errors()).contains("Each ends with `Try 'java -jar rtd.jar --help' for more information.`")
                .doesNotContain("'rtd --help'");
    }

    @Test
    void picturesWrittenBesideTheExamplesAreIgnoredByGit() throws Exception {
        for (String picture : new String[] {"examples/input_rtd.png", "examples/meshes/x.png"}) {
            Process git = new ProcessBuilder("git", "check-ignore", "-q", picture).redirectErrorStream(true).start();
            org.assertj.core.api.Assumptions.assumeThat(git.waitFor(10, java.util.concurrent.TimeUnit.SECONDS)).isTrue();
            org.assertj.core.api.Assumptions.assumeThat(git.exitValue()).as("git and a clone are here").isIn(0, 1);
            assertThat(git.exitValue()).as("git check-ignore %s: 0 means ignored", picture).isZero();
        }
    }

    @Test
    void autoUsesTheViewGridForAnySceneWithObjectsAndItsCellsSkipMostTests() throws IOException {
        Run paper = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("a.png").toString(), "--stats", "--width", "480",
                "--height", "270");
        assertThat(paper.exitCode()).isZero();
        assertThat(paper.err()).contains("2 objects").contains("view grid of");
        // Most cells of the paper's example hold neither sphere: far fewer tests than the loop's 2.
        double testsPerRay = Double.parseDouble(paper.err().replaceAll("(?s).*per ray: ([0-9.]+) intersection.*", "$1"));
        assertThat(testsPerRay).isLessThan(1.0);

        Path cameraOnly = dir.resolve("camera_only.txt");
        Files.writeString(cameraOnly, "orthographic_camera:(0|0|20):(0|0|-1):(50)\n");
        Run empty = Cli.run(cameraOnly.toString(), "-o", dir.resolve("e.png").toString(), "--stats", "--width", "64",
                "--height", "36");
        assertThat(empty.exitCode()).isZero();
        assertThat(empty.err()).contains("no BVH");
    }

    /** "1,234" as 1234. */
    private static long number(String digits) {
        return Long.parseLong(digits.replace(",", ""));
    }

    @Test
    void aPictureGivenAsTheSceneIsNamedAsAPictureNotAsTheOutput() throws IOException {
        Path picture = dir.resolve("out.png");
        assertThat(Cli.run(EXAMPLE.toString(), "-o", picture.toString(), "--width", "16", "--height", "9").exitCode()).isZero();
        byte[] before = Files.readAllBytes(picture);
        Run run = Cli.run(picture.toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("cannot read the scene file", "it is a PNG picture, not a scene");
        assertThat(Files.readAllBytes(picture)).isEqualTo(before);
    }

    @Test
    void moreThanSixteenSamplesAreRefusedBeforeAnyWork() {
        Run run = Cli.run(EXAMPLE.toString(), "--samples", "1000", "--width", "2", "--height", "1", "-o",
                dir.resolve("s.png").toString()); // small, so that a missing check fails here rather than runs for hours
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("'1000' is more than 16", "256 rays a pixel");
        assertThat(dir.resolve("s.png")).doesNotExist();
        assertThat(Cli.run(EXAMPLE.toString(), "--samples", "16", "--width", "8", "--height", "4", "-o", dir.resolve("s.png").toString())
                .exitCode()).isZero();
    }

    @Test
    void explainAndViewTogetherAreMisuse() {
        Run run = Cli.run(EXAMPLE.toString(), "--explain", "1,1", "--view", "cost");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("--explain and --view each take the place of the picture");
    }

    @Test
    void thePapersRunSaysItUsesOneThreadAndNotesTheOptionsItLeavesOut() {
        Run run = Cli.run(EXAMPLE.toString(), "--paper", "--threads", "2", "--accel", "bvh", "--stats", "--width", "32", "--height", "18",
                "-o", dir.resolve("p.png").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("note: --paper renders with the paper's loop on one thread; --accel and --threads are not used",
                "rays on 1 thread");
        Run plain = Cli.run(EXAMPLE.toString(), "--paper", "--width", "32", "--height", "18", "-o", dir.resolve("q.png").toString());
        assertThat(plain.err()).doesNotContain("note:");
    }

    @Test
    void anOutputWithBackslashesGetsANoteThatFoldersAreSeparatedBySlashesHere() {
        Run run = Cli.run(EXAMPLE.toString(), "--width", "8", "--height", "4", "-o", dir.resolve("out\\pic.png").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("has backslashes, which this system keeps in the file's name");
        assertThat(dir.resolve("out\\pic.png")).isRegularFile();
    }
}
