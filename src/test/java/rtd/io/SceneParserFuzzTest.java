package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.file.Path;
import java.time.Duration;
import rtd.scene.Scene;

/**
 * Fuzzes the scene parser with Jazzer. Under {@code mvn verify} it runs in regression mode on
 * the committed seeds in {@code src/test/resources/rtd/io/SceneParserFuzzTestInputs}; to search
 * for new inputs, run {@code JAZZER_FUZZ=1 mvn test -Dtest=SceneParserFuzzTest}.
 */
class SceneParserFuzzTest {

    /** Long enough for any input of the corpus on a slow, shared machine; a hang takes forever. */
    private static final Duration TIME_LIMIT = Duration.ofSeconds(10);

    /** Whatever the bytes: a scene, or the parser's own error with a location; never a hang. */
    @FuzzTest(maxDuration = "60s")
    void anyBytesGiveASceneOrLocatedErrors(byte[] bytes) {
        if (System.getenv("JAZZER_FUZZ") != null) {
            check(bytes); // while fuzzing, a thread per input would slow the search a hundredfold
        } else {
            assertTimeoutPreemptively(TIME_LIMIT, () -> check(bytes));
        }
    }

    private static void check(byte[] bytes) {
        try {
            Scene scene = SceneIO.parseScene("fuzz.txt", bytes, Path.of(""), null);
            assertThat(scene.camera()).isNotNull();
            assertThat(scene.ambient()).isNotNull();
        } catch (SceneException e) {
            assertThat(e.errors()).isNotEmpty().hasSizeLessThanOrEqualTo(SceneException.MAX_ERRORS);
            for (SceneError error : e.errors()) {
                assertThat(error.file()).isEqualTo("fuzz.txt");
                assertThat(error.line()).isPositive();
                assertThat(error.column()).isPositive();
                assertThat(error.message()).isNotBlank();
                assertThat(error.format()).startsWith("fuzz.txt:" + error.line() + ":" + error.column() + ": error: ");
            }
        }
    }
}
