package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

@DisplayName("The temporary file a PNG is written to")
class TemporaryFilesTest {

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
