package rtd;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/**
 * The rules of how rtd's sources are written that a reader sees on the page: a line fits in
 * {@value #MOST_COLUMNS} columns, each character one column (a sign such as × or ≤ as well as a letter).
 */
@DisplayName("The sources")
class SourceStyleTest {

    private static final int MOST_COLUMNS = 120;
    private static final Path MAIN = Path.of("src", "main", "java");

    @Test
    void noLineOfTheMainSourcesPassesOneHundredTwentyColumns() throws IOException {
        List<String> tooLong = new ArrayList<>();
        List<Path> sources;
        try (Stream<Path> files = Files.walk(MAIN)) {
            sources = files.filter(f -> f.toString().endsWith(".java")).sorted().toList();
        }
        for (Path file : sources) {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            for (int i = 0; i < lines.size(); i++) {
                int columns = lines.get(i).codePointCount(0, lines.get(i).length());
                if (columns > MOST_COLUMNS) {
                    tooLong.add(file + ":" + (i + 1) + " (" + columns + " columns)");
                }
            }
        }
        assertThat(sources).isNotEmpty();
        assertThat(tooLong).as("lines of %s longer than %d columns", MAIN, MOST_COLUMNS).isEmpty();
    }
}
