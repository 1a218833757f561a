package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The packaged jar in its own process, where a test in the JVM of the tests cannot go: signals,
 * the locale that Java reads a command line in, a small heap.
 */
@DisplayName("The packaged jar, stopped or started in odd ways")
class InterruptedRunIT {

    private static final String JAVA = Path.of(System.getProperty("java.home"), "bin", "java").toString();
    private static final String JAR = System.getProperty("rtd.jar", "target/rtd.jar");

    @TempDir
    Path dir;

    private record Result(int exitCode, String err) {
    }

    private static Result run(Map<String, String> environment, List<String> command) throws IOException, InterruptedException {
        ProcessBuilder builder = new ProcessBuilder(command).redirectOutput(ProcessBuilder.Redirect.DISCARD);
        builder.environment().putAll(environment);
        Process process = builder.start();
        process.getOutputStream().close();
        byte[] err = process.getErrorStream().readAllBytes();
        assertThat(process.waitFor(60, TimeUnit.SECONDS)).isTrue();
        return new Result(process.exitValue(), new String(err, StandardCharsets.UTF_8));
    }

    private String[] namesIn(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).toArray(String[]::new);
        }
    }

    @ParameterizedTest(name = "SIG{0}")
    @ValueSource(strings = {"TERM", "INT"})
    void aSignalWhileThePngIsWrittenLeavesTheOldFileAndNoTemporaryFile(String signal) throws Exception {
        Path scene = Files.writeString(dir.resolve("empty.txt"), "orthographic_camera:(0|0|20):(0|0|-1):(50)\n");
        Path out = Files.write(dir.resolve("out.png"), new byte[] {1, 2, 3});
        // Large enough that writing the PNG takes about a second, when the signal comes.
        Process rtd = new ProcessBuilder(JAVA, "-Xmx2g", "-jar", JAR, scene.toString(), "-o", out.toString(),
                "--width", "10000", "--height", "10000").redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        Path temporary = awaitTemporaryFile(rtd);
        assertThat(temporary).as("the temporary file, seen while rtd runs").isNotNull();
        Process kill = new ProcessBuilder("kill", "-" + signal, String.valueOf(rtd.pid())).start();
        assertThat(kill.waitFor(10, TimeUnit.SECONDS)).isTrue();
        assertThat(rtd.waitFor(60, TimeUnit.SECONDS)).isTrue();

        assertThat(rtd.exitValue()).as("stopped by the signal, not done").isNotZero();
        assertThat(namesIn(dir)).containsExactlyInAnyOrder("empty.txt", "out.png");
        assertThat(Files.readAllBytes(out)).containsExactly(1, 2, 3);
    }

    /** The temporary file once it appears (rtd is then writing), or null if rtd ends first. */
    private Path awaitTemporaryFile(Process rtd) throws IOException, InterruptedException {
        while (rtd.isAlive()) {
            try (Stream<Path> files = Files.list(dir)) {
                var found = files.filter(p -> p.getFileName().toString().matches("\\.out\\.png\\.[0-9a-f]{16}\\.tmp")).findFirst();
                if (found.isPresent()) {
                    return found.get();
                }
            }
            Thread.sleep(5);
        }
        return null;
    }

    @Test
    void aNonAsciiNameUnderTheCLocaleIsRefusedInWordsAndNoFileIsWritten() throws Exception {
        Path out = dir.resolve("é.png");
        Result result = run(Map.of("LC_ALL", "C"), List.of(JAVA, "-jar", JAR, "examples/input_rtd.txt", "-o", out.toString(),
                "--width", "32", "--height", "18"));
        assertThat(result.exitCode()).isEqualTo(2);
        assertThat(result.err()).contains("cannot be used").contains("LC_ALL=C.UTF-8")
                .doesNotContain("Exception").doesNotContain("java.");
        assertThat(namesIn(dir)).isEmpty();
    }

    @Test
    void aNameThatIsNotValidUtf8IsRefusedAndNoOtherFileIsWritten() throws Exception {
        // Java cannot pass such bytes to a process: the shell's printf makes them.
        String command = "exec \"$0\" -jar \"$1\" examples/input_rtd.txt -o \"$2/$(printf 'a\\377.png')\" --width 32 --height 18";
        Result result = run(Map.of("LC_ALL", "C.UTF-8"), List.of("sh", "-c", command, JAVA, new File(JAR).getPath(), dir.toString()));
        assertThat(result.exitCode()).isEqualTo(2);
        assertThat(result.err()).contains("a?.png' cannot be used: it is not valid UTF-8").doesNotContain("Exception");
        assertThat(namesIn(dir)).isEmpty();
    }

    @Test
    void aSmallHeapIsToldInUnitsThatShowTheDifference() throws Exception {
        Result result = run(Map.of(), List.of(JAVA, "-Xmx16m", "-jar", JAR, "examples/input_rtd.txt", "-o",
                dir.resolve("out.png").toString()));
        assertThat(result.exitCode()).isEqualTo(2);
        assertThat(result.err()).contains("a 1920×1080 image needs 19.8 MiB of memory, but Java may use only ")
                .containsPattern("only \\d+\\.\\d MiB more here \\(limit \\d+\\.\\d MiB\\)")
                .doesNotContain("0.0 GiB");
        assertThat(namesIn(dir)).isEmpty();
    }
}
