package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Runs the packaged {@code target/rtd.jar} in its own process, exactly as a user does. */
@DisplayName("The packaged jar, run with java -jar")
class JarIT {

    @TempDir
    Path dir;

    private record Result(int exitCode, String out, String err) {
    }

    private static Result java(String... args) throws IOException, InterruptedException {
        return java(Map.of(), args);
    }

    private static Result java(Map<String, String> environment, String... args) throws IOException, InterruptedException {
        String jar = System.getProperty("rtd.jar", "target/rtd.jar");
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-jar", jar));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command);
        builder.environment().putAll(environment);
        Process process = builder.start();
        process.getOutputStream().close();
        byte[] out = process.getInputStream().readAllBytes();
        byte[] err = process.getErrorStream().readAllBytes();
        assertThat(process.waitFor(60, TimeUnit.SECONDS)).isTrue();
        return new Result(process.exitValue(), new String(out, StandardCharsets.UTF_8), new String(err, StandardCharsets.UTF_8));
    }

    @Test
    void rendersThePapersExample() throws Exception {
        Path out = dir.resolve("out.png");
        Result result = java("examples/input_rtd.txt", "-o", out.toString());
        assertThat(result.exitCode()).as(result.err()).isZero();
        assertThat(ImageIO.read(out.toFile()).getRGB(460, 490) & 0xFFFFFF).isEqualTo(0xFF0000);
    }

    @Test
    void printsTheVersionFromTheManifest() throws Exception {
        Result result = java("--version");
        assertThat(result.exitCode()).isZero();
        assertThat(result.out()).matches("(?s)rtd \\d+\\.\\d+\\.\\d+.*");
    }

    @Test
    void underAnAsciiLocaleTheExplanationsSignsAreWrittenAsPlainLetters() throws Exception {
        Result ascii = java(Map.of("LC_ALL", "C", "LANG", "C"), "examples/input_rtd.txt", "--explain", "460,490");
        assertThat(ascii.exitCode()).as(ascii.err()).isZero();
        assertThat(ascii.out()).contains("of the 1920 x 1080 picture", "x' = x - w/2 = 460 - 960 = -500", "a = R*R = 1",
                "c = (O - M)*(O - M) - r^2").doesNotContain("?");
        Result unicode = java(Map.of("LC_ALL", "C.UTF-8", "LANG", "C.UTF-8"), "examples/input_rtd.txt", "--explain", "460,490");
        assertThat(unicode.out()).contains("of the 1920 × 1080 picture", "x' = x − w/2 = 460 − 960 = -500", "a = R·R = 1");
    }

    @Test
    void reportsASceneErrorWithoutAStackTrace() throws Exception {
        Path scene = Files.writeString(dir.resolve("bad.txt"), "spere:(1|2|3):(1):(0|0|0)\n");
        Result result = java(scene.toString());
        assertThat(result.exitCode()).isEqualTo(1);
        assertThat(result.err()).contains("bad.txt:1:1: error: unknown statement 'spere'")
                .contains("did you mean 'sphere'?").doesNotContain("Exception").doesNotContain("\tat ");
    }

    @Test
    void readsTheSceneFromStandardInputAndWritesThePictureToStandardOutput() throws Exception {
        Path out = dir.resolve("piped.png");
        String jar = System.getProperty("rtd.jar", "target/rtd.jar");
        Process process = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-jar", jar,
                "-", "-o", "-", "--scale", "0.1")
                .redirectInput(Path.of("examples", "input_rtd.txt").toFile()).redirectOutput(out.toFile()).start();
        byte[] err = process.getErrorStream().readAllBytes();
        assertThat(process.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(process.exitValue()).as(new String(err, StandardCharsets.UTF_8)).isZero();
        assertThat(ImageIO.read(out.toFile()).getRGB(46, 49) & 0xFFFFFF).isEqualTo(0xFF0000);
    }
}
