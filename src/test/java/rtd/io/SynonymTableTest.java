package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/** The table of other words for a statement in docs/errors.md is the table rtd looks words up in. */
@DisplayName("The table of other words for a statement")
class SynonymTableTest {

    @Test
    void inTheDocsIsWordForWordTheOneRtdUses() throws IOException {
        String doc = Files.readString(Path.of("docs", "errors.md"));
        int start = doc.indexOf("| written | suggested |");
        assertThat(start).isNotNegative();
        Map<String, List<String>> documented = new HashMap<>();
        for (String row : doc.substring(start).lines().skip(2).takeWhile(line -> line.startsWith("|")).toList()) {
            String[] cells = row.split("\\|");
            List<String> keywords = List.of(cells[2].replace("`", "").trim().split(" or "));
            for (String word : cells[1].split(",")) {
                documented.put(word.trim(), keywords);
            }
        }
        assertThat(documented).as("the table of docs/errors.md under '| written | suggested |' against rtd.io.Hints.SYNONYMS")
                .isEqualTo(Hints.SYNONYMS);
    }
}
