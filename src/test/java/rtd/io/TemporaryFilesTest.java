package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

@DisplayName("The temporary file a picture is written to")
class TemporaryFilesTest {

    @TempDir
    Path folder;

    @Test
    void aCommittedFileReplacesTheOutputAndLeavesNoTemporaryFile() throws IOException {
        Path output = Files.writeString(folder.resolve("out.png"), "old");
        TemporaryFiles.Replacement temporary = TemporaryFiles.create(output);
        temporary.out().write("new".getBytes(StandardCharsets.UTF_8));
        temporary.out().close();

        temporary.commit();

        assertThat(output).hasContent("new");
        assertThat(folder.toFile().list()).containsExactly("out.png");
    }

    @Test
    void aDiscardedFileLeavesTheOutputAsItWasAndNoTemporaryFile() throws IOException {
        Path output = Files.writeString(folder.resolve("out.png"), "old");
        TemporaryFiles.Replacement temporary = TemporaryFiles.create(output);
        temporary.out().write("half".getBytes(StandardCharsets.UTF_8));

        temporary.discard();

        assertThat(output).hasContent("old");
        assertThat(folder.toFile().list()).containsExactly("out.png");
    }

    @Test
    void isNamedAfterTheOutputHiddenWithSixteenHexDigits() {
        assertThat(TemporaryFiles.name("out.png", 0x1234L)).isEqualTo(".out.png.0000000000001234.tmp");
    }

    @Test
    void hasANameWithin255BytesForAnyLegalOutputNameCutBetweenCharacters() {
        for (String name : new String[] {"x".repeat(255), "é".repeat(127), "😀".repeat(63), "a" + "😀".repeat(63)}) {
            String temporary = TemporaryFiles.name(name, -1L);
            assertThat(temporary.getBytes(StandardCharsets.UTF_8).length).as(name).isLessThanOrEqualTo(255);
            assertThat(temporary).startsWith(".").endsWith(".ffffffffffffffff.tmp").doesNotContain("\uFFFD");
            assertThat(name).startsWith(temporary.substring(1, temporary.length() - 22));
        }
    }
}
