package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.explain.PixelExplanation;
import rtd.image.Picture;
import rtd.io.SceneFile;
import rtd.io.SceneIO;
import rtd.scene.Scene;
import rtd.window.WindowSetup.ClockedScene;

@DisplayName("What the window does, without a screen: explain, copy the camera, save, a broken edit")
class WindowSessionTest {

    @TempDir
    Path dir;

    private SessionHarness window;

    @AfterEach
    void close() {
        window.close();
    }

    @Test
    void aClickedPixelIsExplainedAsExplainTellsIt() throws Exception {
        Scene scene = open("glass_and_mirror");
        window.run(() -> window.session.select(new int[] {100, 50}));
        String explanation = PixelExplanation.of(scene, 100, 50, 160, 90);
        window.awaitTrue(() -> window.display.panel.contains(explanation));
        assertThat(window.display.panel).startsWith("pixel (100, 50) of the 160 × 90 picture of ");
        assertThat(window.on(() -> window.display.rays)).isNotEmpty();
        window.run(() -> window.session.deselect());
        assertThat(window.on(() -> window.display.rays)).isEmpty();
        assertThat(window.on(() -> window.display.panel)).isEqualTo(SidePanel.HELP);
    }

    @Test
    void theCameraIsCopiedAsASceneLineAndRIsTheFilesCameraAgain() throws Exception {
        open("glass_and_mirror");
        window.run(() -> window.session.copyCamera());
        assertThat(window.on(() -> window.display.copied)).isEqualTo("perspective_camera:(0|2.5|9):(0|-0.3|-1):(60)");
        assertThat(window.on(() -> window.display.panel)).contains("perspective_camera:(0|2.5|9):(0|-0.3|-1):(60)");
        window.run(() -> {
            window.session.drag(40, 0, false, window.session.pivot());
            window.session.resetCamera();
            window.session.copyCamera();
        });
        assertThat(window.on(() -> window.display.copied)).isEqualTo("perspective_camera:(0|2.5|9):(0|-0.3|-1):(60)");
    }

    @Test
    void ctrlSSavesTheFullPictureBesideTheScene() throws Exception {
        open("glass_and_mirror");
        Picture full = window.awaitFull();
        window.run(() -> window.session.save());
        Path saved = dir.resolve("scene-window.png");
        window.awaitTrue(() -> window.display.panel.startsWith("Saved the picture as "));
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
        Picture before = window.awaitFull();
        Files.writeString(dir.resolve("scene.txt"), "perspective_camera:(0|0|9):(0|0|-1):(60)\nspher:(0|0|0):(1):(1|2|3)\n");
        ClockedScene saved = new ClockedScene(SceneFile.read(dir.resolve("scene.txt")), scene -> scene);
        window.run(() -> window.session.reloaded(saved));
        assertThat(window.on(() -> window.display.panel)).contains("scene.txt:2:1: error")
                .contains("The last good picture stays");
        Thread.sleep(200);
        assertThat(window.on(() -> window.session.shown().picture().rgb())).isEqualTo(before.rgb());
    }

    @Test
    void aSceneWithoutTheClockHasNoSliderNothingToPlayAndNoClockInTheStatusLine() throws Exception {
        open("glass_and_mirror");
        window.awaitFull();
        assertThat(window.on(() -> window.display.clock)).isNull();
        assertThat(window.on(() -> window.display.status)).doesNotContain("clock");
        window.run(() -> window.session.play());
        assertThat(window.on(() -> window.session.playing())).isFalse();
        assertThat(window.on(() -> window.display.panel)).startsWith("The scene does not use clock");
    }

    private Scene open(String example) throws Exception {
        Path file = dir.resolve("scene.txt");
        Files.copy(Path.of("examples", example + ".txt"), file);
        window = SessionHarness.open(file, 160, 90, 0);
        return SceneIO.readScene(file);
    }
}
