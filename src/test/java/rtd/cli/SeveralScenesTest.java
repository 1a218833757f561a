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

/** {@code java -jar rtd.jar examples/*.txt}: each scene to its own picture beside it. */
@DisplayName("Several scenes in one call")
class SeveralScenesTest {

    private static final Path EXAMPLE = Path.of("examples", "input_rtd.txt");

    @TempDir
    Path dir;

    @Test
    void eachSceneIsRenderedToItsDefaultOutput() throws IOException {
        Path a = Files.copy(EXAMPLE, dir.resolve("a.txt"));
        Path b = Files.copy(Path.of("examples", "depth_test.txt"), dir.resolve("b.txt"));
        Run run = Cli.run(a.toString(), b.toString(), "--width", "64", "--height", "36");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(dir.resolve("a.png")).isRegularFile();
        assertThat(dir.resolve("b.png")).isRegularFile();
    }

    @Test
    void aBrokenSceneDoesNotKeepTheOthersFromBeingRenderedAndTheExitCodeIs1() throws IOException {
        Path bad = Files.writeString(dir.resolve("bad.txt"), "spere:(1|2|3):(1):(0|0|0)\n");
        Path good = Files.copy(EXAMPLE, dir.resolve("good.txt"));
        Run run = Cli.run(bad.toString(), good.toString(), "--width", "64", "--height", "36");
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("bad.txt:1:1: error: unknown statement 'spere'");
        assertThat(dir.resolve("good.png")).isRegularFile();
        assertThat(dir.resolve("bad.png")).doesNotExist();
    }

    @Test
    void oneOutputForSeveralScenesIsMisuseAndNothingIsRendered() throws IOException {
        Path a = Files.copy(EXAMPLE, dir.resolve("a.txt"));
        Run run = Cli.run(a.toString(), a.toString(), "-o", dir.resolve("out.png").toString());
        assertThat(run.exitCode()).isEqualTo(2);
        String message = "rtd: -o names one picture, but 2 scenes were given; leave -o out to write each picture beside "
                + "its scene";
        assertThat(run.err()).startsWith(message + "\n");
        assertThat(Docs.errors()).contains(message);
        assertThat(dir.resolve("out.png")).doesNotExist();
        assertThat(dir.resolve("a.png")).doesNotExist();
    }

    @Test
    void aMistakeOnTheCommandLineForALaterSceneStopsBeforeAnyIsRendered() throws IOException {
        Path a = Files.copy(EXAMPLE, dir.resolve("a.txt"));
        Path itself = Files.copy(EXAMPLE, dir.resolve("b.png"));
        Run run = Cli.run(a.toString(), itself.toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("is the scene file itself");
        assertThat(dir.resolve("a.png")).doesNotExist();
    }

    @Test
    void twoScenesWhosePicturesWouldHaveOneNameAreRefusedBeforeEither() throws IOException {
        Path scene = Files.copy(EXAMPLE, dir.resolve("ball.txt"));
        Path backup = Files.copy(EXAMPLE, dir.resolve("ball.txt~")); // an editor's backup: also ball.png
        Run run = Cli.run(scene.toString(), backup.toString(), "--width", "64", "--height", "36");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("would both write their picture to", "ball.png");
        assertThat(dir.resolve("ball.png")).doesNotExist();
    }

    @Test
    void oneSceneGivenTwiceOrThroughALinkIsMisuse() throws IOException {
        Path scene = Files.copy(EXAMPLE, dir.resolve("ball.txt"));
        Path link = Files.createSymbolicLink(dir.resolve("link.txt"), scene.getFileName());
        for (Path second : new Path[] {scene, link}) {
            Run run = Cli.run(scene.toString(), second.toString(), "--width", "64", "--height", "36");
            assertThat(run.exitCode()).isEqualTo(2);
            assertThat(run.err()).contains("is given twice (or a link to it is); give it once");
        }
        assertThat(dir.resolve("ball.png")).doesNotExist();
        assertThat(dir.resolve("link.png")).doesNotExist();
    }
}
