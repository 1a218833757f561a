package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Component;
import java.awt.Container;
import java.awt.Frame;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import javax.imageio.ImageIO;
import javax.swing.JSlider;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.parallel.Isolated;
import org.junit.jupiter.api.io.TempDir;
import rtd.explain.PixelExplanation;
import rtd.io.SceneIO;
import rtd.scene.Scene;
import rtd.testing.Cli;
import rtd.window.PicturePanel.PixelMapping;

/**
 * The window on a real screen (an X server, Xvfb on CI), driven through the command line and
 * {@link Robot}: skipped with a message where Java has no display.
 */
// a robot clicks and reads the screen: no other window may open meanwhile
@Isolated
@DisplayName("The window on a screen")
class WindowOnScreenTest {

    private static final int W = 320;
    private static final int H = 180;

    @TempDir
    Path dir;

    @Test
    void showsTheSamePixelsAsOExplainsAClickRendersASavedSceneAgainOrbitsAndShowsAView() throws Exception {
        assumeADisplay();
        Path scene = dir.resolve("scene.txt");
        String text = Files.readString(Path.of("examples", "glass_and_mirror.txt"));
        Files.writeString(scene, text);
        CompletableFuture<Cli.Run> run = CompletableFuture.supplyAsync(() -> Cli.run(scene.toString(), "--window",
                "--width", "" + W, "--height", "" + H));
        try {
            PicturePanel panel = await(() -> find(PicturePanel.class), "the window");
            WindowSession session = panel.session();
            assertThat(awaitFinal(session)).isEqualTo(picture(scene, "first.png"));

            // a click on pixel (230, 110), on the glass sphere: its explanation, and its rays drawn
            Robot robot = new Robot();
            Point at = onEdt(() -> {
                PixelMapping map = panel.mapping();
                Point origin = panel.getLocationOnScreen();
                return new Point(origin.x + (int) map.panelX(230.5), origin.y + (int) map.panelY(110.5));
            });
            robot.mouseMove(at.x, at.y);
            robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
            robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
            JTextArea side = find(JTextArea.class);
            String expected = PixelExplanation.of(SceneIO.readScene(scene), 230, 110, W, H);
            await(() -> onEdt(side::getText).contains(expected) ? true : null, "the explanation of the pixel");
            List<RayTreeProjection.Line> drawn = onEdt(() -> panel.rays());
            assertThat(drawn).hasSizeGreaterThan(3);
            screenshot(panel, "window-screenshot.png");

            // saving the file renders it again: the red sphere turned blue
            Files.writeString(scene, text.replace("(230|80|60)", "(60|80|230)"));
            int[] before = session.shown().picture().rgb();
            await(() -> onEdt(() -> session.shown() != null && session.shown().block() == 1
                    && !java.util.Arrays.equals(session.shown().picture().rgb(), before)) ? true : null,
                    "the picture of the saved scene");
            assertThat(awaitFinal(session)).isEqualTo(picture(scene, "second.png"));

            // a drag orbits the camera; once the mouse rests, the full picture of the new view
            FrameRenderer.Pass unmoved = onEdt(session::shown);
            robot.mouseMove(at.x, at.y);
            robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
            for (int step = 1; step <= 10; step++) {
                robot.mouseMove(at.x - 4 * step, at.y);
                Thread.sleep(20);
            }
            robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
            int[] turned = await(() -> onEdt(() -> session.camera().moved() && session.shown().block() == 1
                    && session.shown() != unmoved ? session.shown().picture().rgb() : null), "the orbited picture");
            assertThat(turned).isNotEqualTo(picture(scene, "third.png"));

            // key 2: the cost view, with its legend below the picture
            robot.keyPress(KeyEvent.VK_2);
            robot.keyRelease(KeyEvent.VK_2);
            await(() -> onEdt(() -> session.shown().picture().height() > H && session.shown().block() == 1
                    ? true : null), "the cost view");

            robot.keyPress(KeyEvent.VK_Q);
            robot.keyRelease(KeyEvent.VK_Q);
            assertThat(run.get(20, TimeUnit.SECONDS).exitCode()).isZero();
        } finally {
            for (Frame frame : Frame.getFrames()) {
                SwingUtilities.invokeAndWait(frame::dispose);
            }
        }
    }

    @Test
    void aSceneWithTheClockStartsAtClockCAndPPlaysAndPausesIt() throws Exception {
        assumeADisplay();
        Path orbit = Path.of("examples", "orbit.txt");
        CompletableFuture<Cli.Run> run = CompletableFuture.supplyAsync(() -> Cli.run(orbit.toString(), "--window",
                "--width", "160", "--height", "90", "--clock", "0.25"));
        try {
            PicturePanel panel = await(() -> find(PicturePanel.class), "the window");
            WindowSession session = panel.session();
            assertThat(awaitFinal(session)).isEqualTo(picture(orbit, "clock-0.25.png", 160, 90, "0.25"));
            JSlider slider = await(() -> find(JSlider.class), "the clock slider");
            assertThat(onEdt(() -> slider.isShowing() && slider.getValue() == 250)).isTrue();

            Robot robot = new Robot();
            robot.keyPress(KeyEvent.VK_P);
            robot.keyRelease(KeyEvent.VK_P);
            await(() -> onEdt(() -> session.playing() && session.clock() > 0.3 ? true : null),
                    "the clock playing");
            robot.keyPress(KeyEvent.VK_P);
            robot.keyRelease(KeyEvent.VK_P);
            double paused = await(() -> onEdt(() -> session.playing() ? null : session.clock()),
                    "the clock paused");
            int[] expected = picture(orbit, "paused.png", 160, 90, Double.toString(paused));
            await(() -> onEdt(() -> session.shown().block() == 1
                    && java.util.Arrays.equals(session.shown().picture().rgb(), expected) ? true : null),
                    "the full picture at the paused clock");
            assertThat(onEdt(() -> slider.getValue())).isEqualTo((int) Math.round(paused * 1000));
            screenshot(panel, "window-clock-screenshot.png");

            robot.keyPress(KeyEvent.VK_Q);
            robot.keyRelease(KeyEvent.VK_Q);
            assertThat(run.get(20, TimeUnit.SECONDS).exitCode()).isZero();
        } finally {
            for (Frame frame : Frame.getFrames()) {
                SwingUtilities.invokeAndWait(frame::dispose);
            }
        }
    }

    private static void assumeADisplay() {
        String missing = Window.missingDisplay();
        Assumptions.assumeTrue(missing == null, "no display (" + missing + "): the window's test on a screen is "
                + "skipped; run it under Xvfb, as .ci/run does");
    }

    /** The full picture once the window shows it. */
    private static int[] awaitFinal(WindowSession session) throws Exception {
        return await(() -> onEdt(() -> {
            FrameRenderer.Pass pass = session.shown();
            return pass != null && pass.block() == 1 ? pass.picture().rgb() : null;
        }), "the full picture");
    }

    /** The pixels {@code -o} writes for the scene at the window's size. */
    private int[] picture(Path scene, String name) throws Exception {
        return picture(scene, name, W, H, "0");
    }

    /** The pixels {@code -o} writes for the scene at {@code w × h} and {@code --clock clock}. */
    private int[] picture(Path scene, String name, int w, int h, String clock) throws Exception {
        Path out = dir.resolve(name);
        assertThat(Cli.run(scene.toString(), "--width", "" + w, "--height", "" + h, "--clock", clock, "-o",
                out.toString()).exitCode()).isZero();
        BufferedImage image = ImageIO.read(out.toFile());
        int[] rgb = image.getRGB(0, 0, w, h, null, 0, w);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }

    /** The window as the screen shows it, for the README and a look: target/{@code name}. */
    private static void screenshot(PicturePanel panel, String name) throws Exception {
        Thread.sleep(300);
        Rectangle bounds = onEdt(() -> SwingUtilities.getWindowAncestor(panel).getBounds());
        Path file = Path.of("target", name);
        ImageIO.write(new Robot().createScreenCapture(bounds), "png", file.toFile());
    }

    private static <T extends Component> T find(Class<T> kind) throws Exception {
        return onEdt(() -> {
            for (Frame frame : Frame.getFrames()) {
                T found = find(frame, kind);
                if (found != null && frame.isShowing()) {
                    return found;
                }
            }
            return null;
        });
    }

    private static <T extends Component> T find(Container container, Class<T> kind) {
        for (Component child : container.getComponents()) {
            if (kind.isInstance(child)) {
                return kind.cast(child);
            }
            if (child instanceof Container inner) {
                T found = find(inner, kind);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    private static <T> T onEdt(Supplier<T> question) throws Exception {
        AtomicReference<T> answer = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> answer.set(question.get()));
        return answer.get();
    }

    /** What {@code question} answers once it answers (not null), within 30 s. */
    private static <T> T await(Question<T> question, String what) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (System.nanoTime() < end) {
            T answer = question.ask();
            if (answer != null) {
                return answer;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("the window did not show " + what + " within 30 s");
    }

    private interface Question<T> {
        T ask() throws Exception;
    }
}
