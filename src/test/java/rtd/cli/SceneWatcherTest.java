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
        Path scene = dir.resolve("lesson.txt");
        Path out = dir.resolve("lesson.png");
        Files.writeString(scene, CAMERA + "sphere:(0|0|0):(3):(255|0|0)\n");
        StringWriter err = new StringWriter();
        PrintWriter errors = new PrintWriter(err, true);
        String[] args = {scene.toString(), "-o", out.toString(), "--width", "16", "--height", "16"};
        BlockingQueue<Integer> renders = new LinkedBlockingQueue<>();
        SceneWatcher watcher = new SceneWatcher(scene, () -> {
            CommandLine once = RtdCommand.commandLine();
            once.setErr(errors);
            return once.execute(args);
        }, errors, 10).onRendered(renders::add);
        Thread thread = new Thread(watcher::run, "watcher");
        thread.start();
        try {
            assertThat(next(renders)).isZero();
            assertThat(centre(out)).isEqualTo(0xFF0000);

            save(scene, CAMERA + "sphere:(0|0|0):(3):(0|0|255)\n");
            assertThat(next(renders)).isZero();
            assertThat(centre(out)).isEqualTo(0x0000FF);

            save(scene, CAMERA + "sphere:(0|0|0):(3)(0|255|0)\n"); // a ':' missing
            assertThat(next(renders)).isEqualTo(1);
            assertThat(centre(out)).isEqualTo(0x0000FF);
            assertThat(err.toString()).contains("lesson.txt:2:", "error", "the last good picture stays");
        } finally {
            watcher.stop();
            thread.join();
        }
        assertThat(renders).isEmpty(); // nothing changed after the broken edit: no render more
    }

    @Test
    void rendersASaveMadeInStepsOnlyOnceItIsWhole() throws Exception {
        Path scene = dir.resolve("lesson.txt");
        Path out = dir.resolve("lesson.png");
        Files.writeString(scene, CAMERA + "sphere:(0|0|0):(3):(255|0|0)\n");
        StringWriter err = new StringWriter();
        PrintWriter errors = new PrintWriter(err, true);
        String[] args = {scene.toString(), "-o", out.toString(), "--width", "16", "--height", "16"};
        BlockingQueue<Integer> renders = new LinkedBlockingQueue<>();
        SceneWatcher watcher = new SceneWatcher(scene, () -> {
            CommandLine once = RtdCommand.commandLine();
            once.setErr(errors);
            return once.execute(args);
        }, errors, 10).onRendered(renders::add);
        Thread thread = new Thread(watcher::run, "watcher");
        thread.start();
        try {
            assertThat(next(renders)).isZero();

            Files.writeString(scene, ""); // an editor that empties the file first,
            Thread.sleep(40); // and writes it a few looks later, but within one settling time
            Files.writeString(scene, CAMERA + "sphere:(0|0|0):(3):(0|0|255)\n");

            assertThat(next(renders)).isZero();
            assertThat(centre(out)).isEqualTo(0x0000FF);
            assertThat(err.toString()).doesNotContain("error");
        } finally {
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
