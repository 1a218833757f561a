package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.accel.Accelerator;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** The ways the command line renders: the paper's own code, the paper's loop, the BVH; and what --stats counts. */
@DisplayName("The render modes of the command line")
class RenderModesTest {

    private static final String EXAMPLE = Path.of("examples", "input_rtd.txt").toString();

    @TempDir
    Path dir;

    private byte[] render(String name, String... options) throws IOException {
        Path out = dir.resolve(name + ".png");
        String[] args = new String[options.length + 5];
        args[0] = EXAMPLE;
        args[1] = "-o";
        args[2] = out.toString();
        args[3] = "--threads";
        args[4] = "2";
        System.arraycopy(options, 0, args, 5, options.length);
        Run run = Cli.run(args);
        assertThat(run.exitCode()).as(run.err()).isZero();
        return Files.readAllBytes(out);
    }

    @Test
    void thePapersOwnCodeTheLoopAndTheBvhWriteTheSameFile() throws IOException {
        byte[] paper = render("paper", "--paper");
        assertThat(render("loop", "--accel", "none")).isEqualTo(paper);
        assertThat(render("bvh", "--accel", "bvh")).isEqualTo(paper);
        assertThat(render("auto")).isEqualTo(paper);
        assertThat(render("grid", "--accel", "grid")).isEqualTo(paper);
    }

    @Test
    void statsOfThePapersCodeCountEveryObjectForEveryRay() {
        Run run = Cli.run(EXAMPLE, "-o", dir.resolve("s.png").toString(), "--paper", "--stats");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("2,073,600 rays").contains("per ray: 2.00 intersection tests");
    }

    @Test
    void thePapersCodeParsesItsSceneOnOneThreadWhateverThreadsAreAskedFor() {
        RenderOptions paper = new RenderOptions(List.of(Path.of(EXAMPLE)), null, 1920, 1080, new Scale(1), false, 4,
                Accelerator.Choice.auto, true, 1, false, false, 0);
        assertThat(paper.parseThreads()).isEqualTo(1);
        assertThat(new RenderOptions(List.of(Path.of(EXAMPLE)), null, 1920, 1080, new Scale(1), false, 4,
                Accelerator.Choice.auto, false, 1, false, false, 0).parseThreads()).isEqualTo(4);
    }

    /** One object of each kind with a test of its own, seen from the front, 10 pixels a unit. */
    private static final String MIXED = String.join("\n",
            "orthographic_camera:(0|0|20):(0|0|-1):(10)",
            "sphere:(0|0|0):(1):(255|0|0)",
            "sphere:(3|0|0):(1):(0|255|0)",
            "plane:(0|-2|0):(0|1|0):(0|0|255)",
            "box:(-3|-1|-1):(-2|1|1):(9|9|9)",
            "triangle:(0|2|0):(1|3|0):(-1|3|0):(1|2|3)", "");

    @Test
    void statsCountTheTestsOfEachKindOfObject() throws IOException {
        Path scene = Files.writeString(dir.resolve("mixed.txt"), MIXED);
        Run run = Cli.run(scene.toString(), "-o", dir.resolve("m.png").toString(), "--width", "200", "--height", "100",
                "--accel", "none", "--stats");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("per ray: 5.00 intersection tests (1.00 box, 1.00 plane, 2.00 sphere, 1.00 triangle)");
    }
}
