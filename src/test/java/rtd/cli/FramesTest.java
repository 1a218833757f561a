package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** {@code --clock}, {@code --frames}, {@code --fps} and {@code --subset} (Part III, "Frames on the command line"). */
@DisplayName("Frames of an animation")
class FramesTest {

    /** A sphere that moves from x = −2 at clock 0 to x = 2 at clock 1, its red channel rising with the clock. */
    private static final String MOVING = "ambient:(10|20|30)\northographic_camera:(0|0|20):(0|0|-1):(8)\n"
            + "sphere:(-2 + 4*clock|0|0):(1.5):(55 + 200*clock|100|50)\n";

    @TempDir
    Path dir;

    private Path scene(String text) throws IOException {
        return Files.writeString(dir.resolve("moving.txt"), text);
    }

    private static final String[] SMALL = {"--width", "64", "--height", "36"};

    private Run rtd(String... args) {
        return Cli.run(Stream.concat(Stream.of(args), Stream.of(SMALL)).toArray(String[]::new));
    }

    /** A frame at clock c is the still scene with its numbers worked out by hand: at 0.25, x = −1 and red = 105. */
    @Test
    void aFrameAtAClockIsTheStillSceneWithItsNumbersSubstituted() throws IOException {
        Path moving = scene(MOVING);
        Path still = Files.writeString(dir.resolve("still.txt"), "ambient:(10|20|30)\northographic_camera:(0|0|20):(0|0|-1):(8)\n"
                + "sphere:(-1|0|0):(1.5):(105|100|50)\n");
        Run frames = rtd(moving.toString(), "--frames", "5", "-o", dir.resolve("f.png").toString());
        assertThat(frames.exitCode()).as(frames.err()).isZero();
        Run clock = rtd(moving.toString(), "--clock", "0.25", "-o", dir.resolve("c.png").toString());
        assertThat(clock.exitCode()).as(clock.err()).isZero();
        Run hand = rtd(still.toString(), "-o", dir.resolve("still.png").toString());
        assertThat(hand.exitCode()).as(hand.err()).isZero();
        int[] byHand = pixels(dir.resolve("still.png"));
        assertThat(pixels(dir.resolve("f-001.png"))).isEqualTo(byHand);
        assertThat(pixels(dir.resolve("c.png"))).isEqualTo(byHand);
        assertThat(pixels(dir.resolve("f-000.png"))).isNotEqualTo(byHand);
    }

    @Test
    void framesAreNumberedFromZeroWithThreeDigitsOrAsManyAsTheLastNeeds() throws IOException {
        Path moving = scene(MOVING);
        assertThat(rtd(moving.toString(), "--frames", "3", "-o", dir.resolve("a.png").toString()).exitCode()).isZero();
        assertThat(dir.resolve("a-000.png")).isRegularFile();
        assertThat(dir.resolve("a-002.png")).isRegularFile();
        assertThat(dir.resolve("a-003.png")).doesNotExist();
        FramePlan thousand = new FramePlan(1001, 0, 1000, 24);
        assertThat(thousand.frameFile(Path.of("out.png"), 7)).isEqualTo(Path.of("out-0007.png"));
        assertThat(new FramePlan(60, 0, 59, 24).frameFile(Path.of("x/out"), 7)).isEqualTo(Path.of("x/out-007"));
    }

    @Test
    void thePapersNoteOnTheLightsItLeavesOutIsShownOnceNotOnceAFrame() throws IOException {
        Path lit = scene(MOVING + "light:(0|10|10):(1|1|1)\n");
        Run run = rtd(lit.toString(), "--frames", "3", "--paper", "-o", dir.resolve("p.png").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err().split("--paper draws as the paper does", -1)).hasSize(2);
    }

    /** Frames 2 to 3 of 5 are at clocks 0.5 and 0.75 and named as in the whole animation. */
    @Test
    void aSubsetDrawsItsFramesWithTheirClocksAndNamesInTheWholeAnimation() throws IOException {
        Path moving = scene(MOVING);
        Run all = rtd(moving.toString(), "--frames", "5", "-o", dir.resolve("all.png").toString());
        Run part = rtd(moving.toString(), "--frames", "5", "--subset", "2-3", "-o", dir.resolve("part.png").toString());
        assertThat(all.exitCode()).as(all.err()).isZero();
        assertThat(part.exitCode()).as(part.err()).isZero();
        assertThat(dir.resolve("part-001.png")).doesNotExist();
        assertThat(dir.resolve("part-004.png")).doesNotExist();
        for (int i = 2; i <= 3; i++) {
            assertThat(pixels(dir.resolve("part-00" + i + ".png"))).isEqualTo(pixels(dir.resolve("all-00" + i + ".png")));
        }
        assertThat(new FramePlan(5, 2, 3, 24).clock(3)).isEqualTo(0.75);
        assertThat(part.err()).contains("wrote 2 frames");
        Run one = rtd(moving.toString(), "--frames", "5", "--subset", "4-4", "-o", dir.resolve("one.png").toString());
        assertThat(one.err()).contains("wrote 1 frame, ").endsWith("one-004.png\n");
    }

    /** 5 frames at 10 per second: a delay of 10 hundredths; the NETSCAPE2.0 extension with loop count 0. */
    @Test
    void aGifHasEveryFrameItsDelayAndLoopsForEver() throws IOException {
        Path moving = scene(MOVING);
        Path gif = dir.resolve("movie.gif");
        Run run = rtd(moving.toString(), "--frames", "5", "--fps", "10", "-o", gif.toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            assertThat(reader.getNumImages(true)).isEqualTo(5);
            IIOMetadataNode first = (IIOMetadataNode) reader.getImageMetadata(0).getAsTree("javax_imageio_gif_image_1.0");
            IIOMetadataNode control = (IIOMetadataNode) first.getElementsByTagName("GraphicControlExtension").item(0);
            assertThat(control.getAttribute("delayTime")).isEqualTo("10");
            IIOMetadataNode loop = (IIOMetadataNode) first.getElementsByTagName("ApplicationExtension").item(0);
            assertThat(loop.getAttribute("applicationID") + loop.getAttribute("authenticationCode")).isEqualTo("NETSCAPE2.0");
            assertThat((byte[]) loop.getUserObject()).containsExactly(1, 0, 0);
            BufferedImage last = reader.read(4);
            assertThat(last.getRGB(32 + 16, 18) & 0xFF0000).as("the sphere at x = 2, its red 255").isEqualTo(0xFF0000);
            assertThat(last.getRGB(32 - 16, 18) & 0xFFFFFF).as("background where it was at clock 0")
                    .isNotEqualTo(last.getRGB(32 + 16, 18) & 0xFFFFFF);
        }
        assertThat(new FramePlan(60, 0, 59, 24).delayHundredths()).isEqualTo(4);
        assertThat(new FramePlan(60, 0, 59, 30).delayHundredths()).isEqualTo(3);
    }

    @Test
    void aValueThatBreaksARuleAtSomeFrameStopsTheRunBeforeAnyFrameAndNamesTheClock() throws IOException {
        Path shrinking = scene("orthographic_camera:(0|0|20):(0|0|-1):(8)\nsphere:(0|0|0):(1 - 2*clock):(9|9|9)\n");
        Run run = rtd(shrinking.toString(), "--frames", "5", "-o", dir.resolve("s.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("the radius must be greater than 0, found 1 - 2*clock, which is 0 at clock = 0.5");
        assertThat(dir.resolve("s-000.png")).doesNotExist();
    }

    @Test
    void combinationsThatMeanNothingAreMisuse() throws IOException {
        Path moving = scene(MOVING);
        String out = dir.resolve("x.png").toString();
        String[][] misuses = {
            {"--subset", "0-1", "-o", out}, {"--fps", "10", "-o", out}, {"--frames", "1", "-o", out},
            {"--frames", "4", "--clock", "0.5", "-o", out}, {"--frames", "4", "--explain", "1,1"},
            {"--frames", "4", "--view", "depth"}, {"--frames", "4", "--watch"}, {"--frames", "4", "-o", "-"},
            {"--frames", "4", "--subset", "3-5", "-o", out}, {"--frames", "4", "--subset", "2-1", "-o", out},
            {"--frames", "4", "--subset", "1-2", "-o", dir.resolve("x.gif").toString()}, {"--frames", "4", "--fps", "0"},
            {"--clock", "soon"}};
        for (String[] args : misuses) {
            Run run = rtd(Stream.concat(Stream.of(moving.toString()), Stream.of(args)).toArray(String[]::new));
            assertThat(run.exitCode()).as(String.join(" ", args) + ": " + run.err()).isEqualTo(2);
        }
        assertThat(dir.resolve("x-000.png")).doesNotExist();
        Run two = Cli.run(moving.toString(), moving.toString(), "--frames", "3");
        assertThat(two.exitCode()).isEqualTo(2);
    }

    @Test
    void aSceneWithoutTheClockIsDrawnOnceAndWrittenForEveryFrame() throws IOException {
        Path still = scene("orthographic_camera:(0|0|20):(0|0|-1):(8)\nsphere:(0|0|0):(2*1):(9|9|9)\n");
        Run run = rtd(still.toString(), "--frames", "3", "-o", dir.resolve("s.png").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(pixels(dir.resolve("s-002.png"))).isEqualTo(pixels(dir.resolve("s-000.png")));
    }

    @Test
    void theAnimatedExamplesReadAtEveryClockAndUseIt() throws IOException, SceneException {
        for (String example : new String[] {"orbit", "bouncing_ball", "planets"}) {
            SceneFile file = SceneFile.read(Path.of("examples", example + ".txt"));
            for (double clock : new double[] {0, 0.37, 0.5, 1}) {
                assertThat(file.at(clock, null).objects()).as(example).isNotEmpty();
            }
            assertThat(file.usesClock()).as(example).isTrue();
        }
    }

    /**
     * A lit scene whose camera circles still objects keeps the BVH and the light grids from frame to frame; one
     * whose sphere and light move builds them again. Either way each frame is the picture of its clock drawn alone.
     */
    @Test
    void eachFrameIsThePictureOfItsClockDrawnAloneWhetherTheObjectsMoveOrNot() throws IOException {
        String lit = "ambient:(20|20|40)\nperspective_camera:(12*sin(90*clock)|3|12*cos(90*clock)):(at 0|0|0):(50)\n"
                + "light:(%s|20|10):(255|255|255)\nsphere:(%s|0|0):(1.5):(200|60|40)\n"
                + "plane:(0|-1.5|0):(0|1|0):(90|90|90)\nbox:(2|-1.5|-1):(3|0|1):(40|160|60)\n";
        for (String[] moving : new String[][] {{"-8", "-1"}, {"-8 + 16*clock", "-1 + 2*clock"}}) {
            Path scene = Files.writeString(dir.resolve("lit.txt"), String.format(lit, (Object[]) moving));
            for (String accel : new String[] {"auto", "bvh"}) {
                Run frames = rtd(scene.toString(), "--frames", "3", "--accel", accel, "-o",
                        dir.resolve("f.png").toString());
                assertThat(frames.exitCode()).as(frames.err()).isZero();
                for (int i = 1; i <= 2; i++) {
                    Path alone = dir.resolve("alone-" + i + ".png");
                    Run still = rtd(scene.toString(), "--clock", String.valueOf(i / 2.0), "--accel", accel, "-o",
                            alone.toString());
                    assertThat(still.exitCode()).as(still.err()).isZero();
                    assertThat(pixels(dir.resolve("f-00" + i + ".png"))).as(moving[1] + ", " + accel + ", frame " + i)
                            .isEqualTo(pixels(alone));
                }
            }
        }
    }

    private static int[] pixels(Path png) throws IOException {
        BufferedImage image = ImageIO.read(new File(png.toString()));
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }
}
