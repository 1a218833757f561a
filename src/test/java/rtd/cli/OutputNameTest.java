package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** Output names that are long or odd: the picture is written under the name asked for, or refused. */
@DisplayName("Long and odd output names")
class OutputNameTest {

    private static final Path EXAMPLE = Path.of("examples", "input_rtd.txt");

    @TempDir
    Path dir;

    private String[] namesIn(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).toArray(String[]::new);
        }
    }

    @Test
    void aLegalNameOf244CharactersIsWrittenThoughItsTemporaryNameWouldBeLonger() throws IOException {
        Path out = dir.resolve("x".repeat(240) + ".png");
        Run run = Cli.run(EXAMPLE.toString(), "-o", out.toString(), "--width", "32", "--height", "18");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(namesIn(dir)).containsExactly(out.getFileName().toString());
    }

    @Test
    void aNameThatWasNotValidInTheSystemsEncodingIsRefusedAndNoOtherFileIsWritten() throws IOException {
        // Java turns the bytes of such a name into U+FFFD: writing that name would write another file.
        Path out = dir.resolve("a\uFFFD.png");
        Run run = Cli.run(EXAMPLE.toString(), "-o", out.toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("the name '" + dir.resolve("a?.png") + "' cannot be used: ")
                .doesNotContain("Exception").doesNotContain("java.");
        assertThat(namesIn(dir)).isEmpty();
    }
}
