package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.image.Picture;
import rtd.io.SceneFile;
import rtd.testing.Cli;

@DisplayName("The window's clock, without a screen: the slider, the play key, a camera that follows, a broken value")
class WindowClockTest {

    private static final int W = 160;
    private static final int H = 90;

    @TempDir
    Path dir;

    private SessionHarness window;

    @AfterEach
    void close() {
        if (window != null) {
            window.close();
        }
    }

    @Test
    void theSliderReleasedAtAClockDrawsThePictureMinusOWritesWithThatClock() throws Exception {
        Path orbit = Path.of("examples", "orbit.txt");
        window = SessionHarness.open(orbit, W, H, 0);
        window.awaitFull();
        assertThat(window.on(() -> window.display.clock)).isEqualTo(0.0);
        int[] expected = picture(orbit, "0.25");
        assertThat(window.on(() -> window.session.shown().picture().rgb())).isNotEqualTo(expected);

        window.run(() -> window.session.atClock(0.2, false));
        window.run(() -> window.session.atClock(0.25, true));
        window.awaitTrue(() -> Arrays.equals(window.session.shown().picture().rgb(), expected));
        assertThat(window.on(() -> window.display.clock)).isEqualTo(0.25);
        assertThat(window.on(() -> window.display.status)).startsWith("picture · clock 0.250 · 160 × 90");
    }

    @Test
    void theWindowStartsAtTheClockGivenAndItsCameraFollowsTheFilesUnlessMoved() throws Exception {
        Path orbit = Path.of("examples", "orbit.txt");
        window = SessionHarness.open(orbit, W, H, 0.5);
        assertThat(window.awaitFull().rgb()).isEqualTo(picture(orbit, "0.5"));

        window.run(() -> window.session.atClock(0.25, true));
        assertThat(copied()).isEqualTo(fileCamera(orbit, 0.25));

        window.run(() -> window.session.drag(30, 10, false, window.session.pivot()));
        String moved = copied();
        assertThat(moved).isNotEqualTo(fileCamera(orbit, 0.25));
        window.run(() -> window.session.atClock(0.75, true));
        assertThat(copied()).isEqualTo(moved);

        window.run(() -> window.session.resetCamera());
        assertThat(copied()).isEqualTo(fileCamera(orbit, 0.75));
    }

    @Test
    void playAdvancesTheClockWithTimeAndWrapsRoundTo0() throws Exception {
        // one pass in 5 s: 1.25 s is a quarter; 0.75 and a further 1.5 s is 1.05, which wraps to 0.05
        assertThat(WindowSession.next(0, 1_250_000_000L)).isEqualTo(0.25);
        assertThat(WindowSession.next(0.75, 1_500_000_000L)).isCloseTo(0.05, within(1e-12));
        assertThat(WindowSession.next(1, 0)).isZero();

        window = SessionHarness.open(Path.of("examples", "orbit.txt"), W, H, 0);
        window.awaitFull();
        window.run(() -> window.session.tick(1_000_000_000L));
        assertThat(window.on(() -> window.session.clock())).isZero(); // not playing yet
        window.run(() -> window.session.play());
        window.run(() -> window.session.tick(1_250_000_000L));
        assertThat(window.on(() -> window.display.clock)).isEqualTo(0.25);
        window.run(() -> window.session.tick(4_000_000_000L));
        assertThat(window.on(() -> window.session.clock())).isCloseTo(0.05, within(1e-12));
        window.run(() -> window.session.play());
        assertThat(window.on(() -> window.session.playing())).isFalse();
        window.awaitTrue(() -> window.display.status.startsWith("picture · clock 0.050 · 160 × 90 · last frame"));

        window.run(() -> window.session.play());
        window.run(() -> window.session.slid(0.5, true)); // the user takes the slider: playing stops
        assertThat(window.on(() -> window.session.playing())).isFalse();
        window.run(() -> window.session.tick(1_000_000_000L));
        assertThat(window.on(() -> window.session.clock())).isEqualTo(0.5);
    }

    @Test
    void aValueBrokenAtAClockShowsItsMessageAndKeepsTheLastGoodPicture() throws Exception {
        Path scene = dir.resolve("scene.txt");
        Files.writeString(scene, "perspective_camera:(0|0|9):(0|0|-1):(60)\nsphere:(0|0|0):(2 - 4*clock):(255|0|0)\n");
        window = SessionHarness.open(scene, W, H, 0);
        Picture before = window.awaitFull();

        window.run(() -> window.session.atClock(0.75, true));
        String panel = window.on(() -> window.display.panel);
        assertThat(panel).contains("scene.txt:2:").contains("at clock = 0.75")
                .endsWith("The last good picture stays; fix the scene and save it again, or move the clock.");
        assertThat(window.on(() -> window.display.clock)).isEqualTo(0.75);
        Thread.sleep(200);
        assertThat(window.on(() -> window.session.shown().picture().rgb())).isEqualTo(before.rgb());

        window.run(() -> window.session.atClock(0.25, true));
        assertThat(window.on(() -> window.display.panel)).isEqualTo(SidePanel.HELP);
        int[] smaller = picture(scene, "0.25");
        window.awaitTrue(() -> Arrays.equals(window.session.shown().picture().rgb(), smaller));
    }

    private String copied() throws Exception {
        window.run(() -> window.session.copyCamera());
        return window.on(() -> window.display.copied);
    }

    private static String fileCamera(Path scene, double clock) throws Exception {
        return CameraController.line(SceneFile.read(scene).at(clock, null).camera());
    }

    /** The pixels {@code -o} writes for {@code scene} at the window's size with {@code --clock clock}. */
    private int[] picture(Path scene, String clock) throws Exception {
        Path out = dir.resolve("clock-" + clock + ".png");
        assertThat(Cli.run(scene.toString(), "--width", "" + W, "--height", "" + H, "--clock", clock, "-o",
                out.toString()).exitCode()).isZero();
        BufferedImage image = ImageIO.read(out.toFile());
        int[] rgb = image.getRGB(0, 0, W, H, null, 0, W);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }
}
