package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

@DisplayName("Watching a scene")
class SceneWatcherTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(4)\n";

    @TempDir
    Path dir;

    @Test
    void rendersAgainAfterAnEditAndKeepsTheLastGoodPictureAfterABrokenOne() throws Exception {
        BlockingQueue<Integer> renders;
        try (Watching watching = new Watching(dir, CAMERA + "sphere:(0|0|0):(3):(255|0|0)\n")) {
            renders = watching.renders;
            assertThat(next(renders)).isZero();
            assertThat(centre(watching.out)).isEqualTo(0xFF0000);

            save(watching.scene, CAMERA + "sphere:(0|0|0):(3):(0|0|255)\n");
            assertThat(next(renders)).isZero();
            assertThat(centre(watching.out)).isEqualTo(0x0000FF);

            save(watching.scene, CAMERA + "sphere:(0|0|0):(3)(0|255|0)\n"); // a ':' missing
            assertThat(next(renders)).isEqualTo(1);
            assertThat(centre(watching.out)).isEqualTo(0x0000FF);
            assertThat(watching.err.toString()).contains("lesson.txt:2:", "error", "the last good picture stays");
        }
        assertThat(renders).isEmpty(); // nothing changed after the broken edit: no render more
    }

    @Test
    void aBrokenFirstSaveSaysThereIsNoPictureYetAndTheFixedOneRenders() throws Exception {
        try (Watching watching = new Watching(dir, CAMERA + "sphere:(0|0|0):(3)(0|255|0)\n")) { // a ':' missing
            assertThat(next(watching.renders)).isEqualTo(1);
            assertThat(watching.err.toString()).contains("no picture yet").doesNotContain("the last good picture stays");

            save(watching.scene, CAMERA + "sphere:(0|0|0):(3):(0|255|0)\n");
            assertThat(next(watching.renders)).isZero();
            assertThat(centre(watching.out)).isEqualTo(0x00FF00);
        }
    }

    @Test
    void aMistakeOnTheCommandLineEndsTheWatchAtOnceWithItsExitCode() throws Exception {
        Path scene = Files.writeString(dir.resolve("lesson.txt"), CAMERA);
        java.io.StringWriter err = new java.io.StringWriter();
        int code = org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(20),
                () -> new SceneWatcher(scene, () -> 2, new java.io.PrintWriter(err, true), 10).run());
        assertThat(code).isEqualTo(2); // no edit of the scene could mend it: no watching
        assertThat(err.toString()).doesNotContain("watching", "picture");
    }

    @Test
    void rendersASaveMadeInStepsOnlyOnceItIsWhole() throws Exception {
        try (Watching watching = new Watching(dir, CAMERA + "sphere:(0|0|0):(3):(255|0|0)\n")) {
            assertThat(next(watching.renders)).isZero();

            Files.writeString(watching.scene, ""); // an editor that empties the file first,
            Thread.sleep(40); // and writes it a few looks later, but within one settling time
            Files.writeString(watching.scene, CAMERA + "sphere:(0|0|0):(3):(0|0|255)\n");

            assertThat(next(watching.renders)).isZero();
            assertThat(centre(watching.out)).isEqualTo(0x0000FF);
            assertThat(watching.err.toString()).doesNotContain("error");
        }
    }

    /**
     * A watcher of {@code lesson.txt} in {@code folder}, written with {@code text} first, on a
     * thread of its own, looking every 10 ms and rendering 16 × 16 to {@code lesson.png};
     * closing it stops the watcher and waits for it.
     */
    private static final class Watching implements AutoCloseable {
        final Path scene;
        final Path out;
        final StringWriter err = new StringWriter();
        final BlockingQueue<Integer> renders = new LinkedBlockingQueue<>();
        private final SceneWatcher watcher;
        private final Thread thread;

        Watching(Path folder, String text) throws IOException {
            scene = folder.resolve("lesson.txt");
            out = folder.resolve("lesson.png");
            Files.writeString(scene, text);
            PrintWriter errors = new PrintWriter(err, true);
            String[] args = {scene.toString(), "-o", out.toString(), "--width", "16", "--height", "16"};
            watcher = new SceneWatcher(scene, () -> {
                CommandLine once = RtdCommand.commandLine();
                once.setErr(errors);
                return once.execute(args);
            }, errors, 10).onRendered(renders::add);
            thread = new Thread(watcher::run, "watcher");
            thread.start();
        }

        @Override
        public void close() throws InterruptedException {
            watcher.stop();
            thread.join();
        }
    }

    /**
     * Saves {@code text} as many editors do, whole: written beside the file, then moved over it.
     * (A save in steps is the other test's subject.)
     */
    private static void save(Path file, String text) throws IOException {
        Path beside = file.resolveSibling(file.getFileName() + ".saving");
        Files.writeString(beside, text);
        Files.move(beside, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    /** The next render's exit code; the timeout only keeps a broken watcher from hanging the build. */
    private static int next(BlockingQueue<Integer> renders) throws InterruptedException {
        Integer code = renders.poll(60, TimeUnit.SECONDS);
        assertThat(code).as("a render").isNotNull();
        return code;
    }

    private static int centre(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        return image.getRGB(8, 8) & 0xFFFFFF;
    }
}
