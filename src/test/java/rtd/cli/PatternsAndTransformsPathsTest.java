package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;
import rtd.testing.Scenes;

/**
 * Every kind of shape, patterned and transformed, draws the same file on every path of the command line:
 * the paper's own code, the paper's loop, the BVH and the grids, flat and shaded.
 */
@DisplayName("Patterned and transformed shapes on every path of the command line")
class PatternsAndTransformsPathsTest {

    private static final String SHAPES = Scenes.EVERY_SHAPE;

    @TempDir
    Path dir;

    private byte[] render(Path scene, String name, String... options) throws IOException {
        Path out = dir.resolve(name + ".png");
        String[] fixed = {scene.toString(), "-o", out.toString(), "--threads", "2", "--width", "160", "--height", "90",
            "--no-progress"};
        String[] args = new String[fixed.length + options.length];
        System.arraycopy(fixed, 0, args, 0, fixed.length);
        System.arraycopy(options, 0, args, fixed.length, options.length);
        Run run = Cli.run(args);
        assertThat(run.exitCode()).as(run.err()).isZero();
        return Files.readAllBytes(out);
    }

    private Path scene(String text) throws IOException {
        Files.copy(Path.of("examples", "meshes", "icosphere_1.obj"), dir.resolve("ico.obj"));
        return Files.writeString(dir.resolve("shapes.txt"), text);
    }

    @Test
    void inFlatColoursThePapersCodeTheLoopTheBvhAndTheGridWriteTheSameFile() throws IOException {
        Path scene = scene(SHAPES);
        byte[] paper = render(scene, "paper", "--paper");
        assertThat(render(scene, "loop", "--accel", "none")).isEqualTo(paper);
        assertThat(render(scene, "bvh", "--accel", "bvh")).isEqualTo(paper);
        assertThat(render(scene, "grid", "--accel", "grid")).isEqualTo(paper);
    }

    @Test
    void shadedTheLoopTheBvhAndTheGridsWriteTheSameFile() throws IOException {
        Path scene = scene(SHAPES + "material:(shiny):(reflective=0.4)\nlight:(-5|8|6):(255|255|255)\n"
                + "light:(6|5|2):(120|120|160)\nsphere:(0|0.5|4):(0.5):(255|255|255):(small):(shiny)\n");
        byte[] loop = render(scene, "loop", "--accel", "none");
        assertThat(render(scene, "bvh", "--accel", "bvh")).isEqualTo(loop);
        assertThat(render(scene, "grid", "--accel", "grid")).isEqualTo(loop);
    }

    @Test
    void whittedsPictureIsTheSameOnEveryPath() throws IOException {
        Path scene = Path.of("examples", "whitted_1980.txt");
        byte[] loop = render(scene, "loop", "--accel", "none");
        assertThat(render(scene, "bvh", "--accel", "bvh")).isEqualTo(loop);
        assertThat(render(scene, "grid", "--accel", "grid")).isEqualTo(loop);
    }
}
