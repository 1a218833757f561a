package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowable;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.accel.Accelerator;
import rtd.camera.OrthographicCamera;
import rtd.cli.WindowRun;
import rtd.scene.Scene;
import rtd.testing.Cli;
import rtd.testing.Scenes;
import rtd.view.View;
import rtd.window.WindowSetup.Engine;

@DisplayName("The window's renders: passes of 8, 4, 2 and 1, the last -o's own pixels, and cancelled by a newer one")
class FrameRendererTest {

    private static final Engine ENGINE = WindowRun.engine(Accelerator.Choice.auto, 2);

    @TempDir
    Path dir;

    @Test
    void aStillPictureComesInPassesOf8421AndEndsWithThePixelsOfO() throws Exception {
        Scene scene = Scenes.example("glass_and_mirror");
        List<FrameRenderer.Pass> passes = new ArrayList<>();
        render(scene, null, FrameRenderer.STILL, passes::add);
        assertThat(passes).extracting(FrameRenderer.Pass::block).containsExactly(8, 4, 2, 1);
        assertThat(passes.get(3).picture().rgb()).isEqualTo(written("examples/glass_and_mirror.txt"));
        // a coarse pass shows the colour of each block's top left pixel of the final picture
        int[] coarse = passes.get(0).picture().rgb();
        int[] full = passes.get(3).picture().rgb();
        assertThat(coarse[37 * 160 + 83]).isEqualTo(full[32 * 160 + 80]);
    }

    @Test
    void thePapersFlatSceneEndsWithThePixelsOfOToo() throws Exception {
        // -o at --scale 0.125: 240 × 135 pixels at zoom 6.25, both spheres in view
        Scene paper = Scenes.example("input_rtd");
        OrthographicCamera camera = (OrthographicCamera) paper.camera();
        Scene scaled = new Scene(paper.ambient(), new OrthographicCamera(camera.position(), camera.direction(), 6.25f),
                paper.objects(), paper.lights());
        List<FrameRenderer.Pass> passes = new ArrayList<>();
        renderer(240, 135).render(scaled, scaled.camera(), null, FrameRenderer.STILL, passes::add);
        Path out = dir.resolve("paper.png");
        assertThat(Cli.run("examples/input_rtd.txt", "--scale", "0.125", "-o", out.toString()).exitCode()).isZero();
        assertThat(passes.get(3).picture().rgb()).isEqualTo(rgb(ImageIO.read(out.toFile())))
                .contains(0xFF0000, 0x007FFF); // the red and the blue sphere
    }

    @Test
    void aViewIsDrawnWithItsLegendAsViewDrawsIt() throws Exception {
        Scene scene = Scenes.example("glass_and_mirror");
        List<FrameRenderer.Pass> passes = new ArrayList<>();
        render(scene, View.cost, FrameRenderer.RESTED, passes::add);
        Path out = dir.resolve("cost.png");
        assertThat(Cli.run("examples/glass_and_mirror.txt", "--width", "160", "--height", "90", "--view", "cost", "-o",
                out.toString()).exitCode()).isZero();
        BufferedImage image = ImageIO.read(out.toFile());
        assertThat(passes.get(0).picture().height()).isEqualTo(image.getHeight()).isGreaterThan(90);
        assertThat(passes.get(0).picture().rgb()).isEqualTo(rgb(image));
        assertThat(passes.get(0).legend()).startsWith("cost: intersection tests per camera ray");
    }

    @Test
    void aNewRenderCancelsTheOneInProgress() throws Exception {
        CountDownLatch started = new CountDownLatch(1);
        AtomicBoolean finished = new AtomicBoolean();
        CountDownLatch second = new CountDownLatch(1);
        try (FrameRenderer loop = renderer(160, 90)) {
            loop.submit(() -> {
                started.countDown();
                try {
                    Thread.sleep(30_000); // a long render: interrupted as FrameRenderer's bands would be
                    finished.set(true);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, true);
            assertThat(started.await(10, TimeUnit.SECONDS)).isTrue();
            loop.submit(second::countDown, true);
            assertThat(second.await(10, TimeUnit.SECONDS)).isTrue();
        }
        assertThat(finished).isFalse();
    }

    @Test
    void aFrameStillWaitingIsDroppedForANewerOne() throws Exception {
        CountDownLatch started = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        AtomicBoolean dropped = new AtomicBoolean();
        CountDownLatch newer = new CountDownLatch(1);
        try (FrameRenderer loop = renderer(160, 90)) {
            loop.submit(() -> {
                started.countDown();
                try {
                    release.await(); // a moving frame in progress
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, false);
            // the two frames below wait behind it: without this, the first could start alone and the second with it
            assertThat(started.await(10, TimeUnit.SECONDS)).isTrue();
            loop.submit(() -> dropped.set(true), false);
            loop.submit(newer::countDown, false);
            release.countDown();
            assertThat(newer.await(10, TimeUnit.SECONDS)).isTrue();
        }
        assertThat(dropped).isFalse();
    }

    @Test
    void anErrorInARenderIsToldAsOnAnyThreadNotSwallowed() throws Exception {
        CountDownLatch told = new CountDownLatch(1);
        Thread.UncaughtExceptionHandler before = Thread.getDefaultUncaughtExceptionHandler();
        Thread.setDefaultUncaughtExceptionHandler((thread, e) -> {
            if (e instanceof OutOfMemoryError) {
                told.countDown();
            }
        });
        try (FrameRenderer loop = renderer(160, 90)) {
            loop.submit(() -> {
                throw new OutOfMemoryError("a render too large for the heap");
            }, false);
            assertThat(told.await(10, TimeUnit.SECONDS)).isTrue();
        } finally {
            Thread.setDefaultUncaughtExceptionHandler(before);
        }
    }

    @Test
    void anInterruptedRenderShowsNoFurtherPass() {
        Scene scene = Scenes.example("glass_and_mirror");
        List<FrameRenderer.Pass> passes = new ArrayList<>();
        Thread.currentThread().interrupt();
        try {
            catchThrowable(() -> render(scene, null, FrameRenderer.STILL, passes::add)); // cancelled: it may throw
        } finally {
            Thread.interrupted();
        }
        assertThat(passes).isEmpty();
    }

    private static void render(Scene scene, View view, List<Integer> blocks, Consumer<FrameRenderer.Pass> listener) {
        renderer(160, 90).render(scene, scene.camera(), view, blocks, listener);
    }

    /** A renderer of {@code w × h} pictures with one ray per pixel on 2 threads, its frames shown nowhere. */
    private static FrameRenderer renderer(int w, int h) {
        return new FrameRenderer(new WindowSetup(null, null, null, ENGINE, w, h, 1, 2, 0), Runnable::run,
                (pass, newest) -> { }, e -> { });
    }

    private int[] written(String scene) throws Exception {
        Path out = dir.resolve("o.png");
        assertThat(Cli.run(scene, "--width", "160", "--height", "90", "-o", out.toString()).exitCode()).isZero();
        return rgb(ImageIO.read(out.toFile()));
    }

    private static int[] rgb(BufferedImage image) {
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }
}
