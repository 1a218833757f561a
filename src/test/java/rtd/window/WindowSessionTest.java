package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.cli.WindowOptions;
import rtd.explain.PixelExplanation;
import rtd.image.Picture;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.scene.Scene;

@DisplayName("What the window does, without a screen: explain, copy the camera, save, a broken edit")
class WindowSessionTest {

    @TempDir
    Path dir;

    /** The window's thread, as Swing's would be. */
    private final ExecutorService ui = Executors.newSingleThreadExecutor();
    private final Shown display = new Shown();
    private WindowSession session;

    @AfterEach
    void close() {
        ui.submit(() -> session.close());
        ui.shutdown();
    }

    @Test
    void aClickedPixelIsExplainedAsExplainTellsIt() throws Exception {
        Scene scene = open("glass_and_mirror");
        on(() -> {
            session.select(new int[] {100, 50});
            return null;
        });
        String explanation = PixelExplanation.of(scene, 100, 50, 160, 90);
        awaitTrue(() -> display.panel.contains(explanation));
        assertThat(display.panel).startsWith("pixel (100, 50) of the 160 × 90 picture of ");
        assertThat(on(() -> display.rays)).isNotEmpty();
        on(() -> {
            session.deselect();
            return null;
        });
        assertThat(on(() -> display.rays)).isEmpty();
        assertThat(on(() -> display.panel)).isEqualTo(Keys.HELP);
    }

    @Test
    void theCameraIsCopiedAsASceneLineAndRIsTheFilesCameraAgain() throws Exception {
        open("glass_and_mirror");
        on(() -> {
            session.copyCamera();
            return null;
        });
        assertThat(on(() -> display.copied)).isEqualTo("perspective_camera:(0|2.5|9):(0|-0.3|-1):(60)");
        assertThat(on(() -> display.panel)).contains("perspective_camera:(0|2.5|9):(0|-0.3|-1):(60)");
        on(() -> {
            session.drag(40, 0, false, session.pivot());
            session.resetCamera();
            session.copyCamera();
            return null;
        });
        assertThat(on(() -> display.copied)).isEqualTo("perspective_camera:(0|2.5|9):(0|-0.3|-1):(60)");
    }

    @Test
    void ctrlSSavesTheFullPictureBesideTheScene() throws Exception {
        open("glass_and_mirror");
        Picture full = awaitFull();
        on(() -> {
            session.save();
            return null;
        });
        Path saved = dir.resolve("scene-window.png");
        awaitTrue(() -> display.panel.startsWith("Saved the picture as "));
        BufferedImage image = ImageIO.read(saved.toFile());
        int[] rgb = image.getRGB(0, 0, 160, 90, null, 0, 160);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        assertThat(rgb).isEqualTo(full.rgb());
    }

    @Test
    void aBrokenEditShowsItsMistakesAndKeepsTheLastGoodPicture() throws Exception {
        open("glass_and_mirror");
        Picture before = awaitFull();
        SceneException mistakes = null;
        try {
            SceneIO.parseScene("scene.txt", "perspective_camera:(0|0|9):(0|0|-1):(60)\nspher:(0|0|0):(1):(1|2|3)\n");
        } catch (SceneException e) {
            mistakes = e;
        }
        SceneException broken = mistakes;
        on(() -> {
            session.reloaded(null, broken, null);
            return null;
        });
        assertThat(on(() -> display.panel)).contains("scene.txt:2:1: error").contains("The last good picture stays");
        Thread.sleep(200);
        assertThat(on(() -> session.shown().picture().rgb())).isEqualTo(before.rgb());
    }

    private Scene open(String example) throws Exception {
        Path file = dir.resolve("scene.txt");
        Files.copy(Path.of("examples", example + ".txt"), file);
        Scene scene = SceneIO.readScene(file);
        WindowSetup setup = new WindowSetup(file, () -> SceneIO.readScene(file), changed -> () -> { },
                WindowOptions.engine("auto", 2), 160, 90, 1, 2);
        on(() -> {
            session = new WindowSession(setup, scene, display, ui);
            session.start();
            return null;
        });
        return scene;
    }

    private Picture awaitFull() throws Exception {
        awaitTrue(() -> session.shown() != null && session.shown().block() == 1);
        return on(() -> session.shown().picture());
    }

    private <T> T on(Callable<T> question) throws Exception {
        return ui.submit(question).get(30, TimeUnit.SECONDS);
    }

    private void awaitTrue(Callable<Boolean> question) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (System.nanoTime() < end) {
            if (on(question)) {
                return;
            }
            Thread.sleep(20);
        }
        throw new AssertionError("not within 30 s");
    }

    /** What the window would show, read and written on the window's thread only. */
    private static final class Shown implements Display {
        String panel = "";
        String copied;
        List<RayTreeProjection.Line> rays = List.of();

        @Override
        public void picture(Picture picture) {
        }

        @Override
        public void rays(List<RayTreeProjection.Line> lines) {
            rays = lines;
        }

        @Override
        public void panel(String text) {
            panel = text;
        }

        @Override
        public void status(String text) {
        }

        @Override
        public void copy(String text) {
            copied = text;
        }
    }
}
