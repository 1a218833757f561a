package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.accel.Accelerator.Choice;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

@DisplayName("--window on the command line: what it refuses, its eye on the files, and no display")
class WindowOptionsTest {

    private static final String EXAMPLE = Path.of("examples", "input_rtd.txt").toString();

    @TempDir
    Path dir;

    @Test
    void optionsThatMeanNothingInAWindowAreRefusedWithWhatTheWindowDoesInstead() {
        String[][] refused = {
            {"--explain", "1,1"}, {"--view", "cost"}, {"--watch"}, {"--export-pov", dir.resolve("s.pov").toString()},
            {"--paper"}, {"-o", dir.resolve("out.png").toString()}, {"-o", "-"}};
        for (String[] option : refused) {
            List<String> args = new ArrayList<>(List.of(EXAMPLE, "--window"));
            args.addAll(List.of(option));
            Run run = Cli.run(args.toArray(String[]::new));
            assertThat(run.exitCode()).as(option[0]).isEqualTo(2);
            assertThat(run.err()).startsWith("rtd: --window and " + option[0] + " do not go together: ")
                    .contains("Try 'java -jar rtd.jar --help'");
        }
        String message = Cli.run(EXAMPLE, "--window", "--explain", "1,1").err().lines().findFirst().orElseThrow();
        assertThat(message).isEqualTo("rtd: --window and --explain do not go together: a click on a pixel explains it");
        assertThat(Docs.errors()).contains(message);
    }

    @Test
    void framesAreRefusedWithTheClockToGiveInstead() {
        Run run = Cli.run(EXAMPLE, "--window", "--frames", "3");
        assertThat(run.exitCode()).isEqualTo(2);
        String message = run.err().lines().findFirst().orElseThrow();
        assertThat(message).isEqualTo("rtd: --window works on one picture, not on --frames; give --clock C for the "
                + "moment you want");
        assertThat(Docs.errors()).contains(message.replace("--window", "--explain")).contains("or `--window` with");
    }

    @Test
    void severalScenesOrStandardInputAreRefused() {
        Run two = Cli.run(EXAMPLE, EXAMPLE, "--window");
        assertThat(two.exitCode()).isEqualTo(2);
        String several = two.err().lines().findFirst().orElseThrow();
        assertThat(several).isEqualTo("rtd: --window opens one scene file, but 2 were given; open each in a window of "
                + "its own");
        Run stdin = Cli.run("-", "--window");
        assertThat(stdin.exitCode()).isEqualTo(2);
        String standardInput = stdin.err().lines().findFirst().orElseThrow();
        assertThat(standardInput).isEqualTo("rtd: --window needs a scene file to watch; it cannot open standard input "
                + "('-')");
        assertThat(Docs.errors()).contains(several).contains(standardInput);
    }

    @Test
    void theWindowHearsOfEachSaveOfTheSceneButNotOfItsFirstLook() throws Exception {
        Path scene = dir.resolve("scene.txt");
        Files.copy(Path.of(EXAMPLE), scene);
        RenderOptions options = new RenderOptions(List.of(scene), null, 160, 90, new Scale(1), true, 1, Choice.auto,
                false, 1, false, false, 0);
        AtomicInteger saves = new AtomicInteger();
        AutoCloseable watching = WindowRun.watch(options).start(saves::incrementAndGet);
        try {
            Thread.sleep(3 * SceneWatcher.POLL_MILLIS);
            assertThat(saves).hasValue(0);
            Files.writeString(scene, "ambient:(0|0|0)\n", StandardOpenOption.APPEND);
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (saves.get() == 0 && System.nanoTime() < end) {
                Thread.sleep(20);
            }
            assertThat(saves).hasValue(1);
        } finally {
            watching.close();
        }
    }

    @Test
    void withoutADisplayTheExitCodeIs2WithOneLineAndNoStackTrace() throws Exception {
        // a new JVM without DISPLAY, as on a server or over SSH without X
        ProcessBuilder command = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "rtd.cli.RtdCommand", EXAMPLE, "--window", "--clock", "0.5"); // --clock is the window's starting clock
        command.environment().remove("DISPLAY");
        command.environment().remove("WAYLAND_DISPLAY");
        command.redirectOutput(dir.resolve("out.txt").toFile());
        command.redirectError(dir.resolve("err.txt").toFile());
        Process process = command.start();
        assertThat(process.waitFor(60, TimeUnit.SECONDS)).isTrue();
        String err = Files.readString(dir.resolve("err.txt"), StandardCharsets.UTF_8);
        assertThat(process.exitValue()).isEqualTo(2);
        String message = "rtd: --window needs a desktop, and there is none here (DISPLAY is not set); -o writes the "
                + "picture to a file instead, such as -o picture.png";
        assertThat(err).isEqualTo(message + System.lineSeparator());
        assertThat(Docs.errors()).contains(message);
    }
}
