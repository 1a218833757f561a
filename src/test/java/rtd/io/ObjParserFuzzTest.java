package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.time.Duration;
import java.util.Arrays;

/**
 * Fuzzes the OBJ reader with Jazzer, as {@link SceneParserFuzzTest} does the scene parser. Under
 * {@code mvn verify} it runs in regression mode on the committed seeds in
 * {@code src/test/resources/rtd/io/ObjReaderFuzzTestInputs}; to search for new inputs, run
 * {@code JAZZER_FUZZ=1 mvn test -Dtest=ObjReaderFuzzTest}.
 */
class ObjReaderFuzzTest {

    /** Long enough for any input of the corpus on a slow, shared machine; a hang takes forever. */
    private static final Duration TIME_LIMIT = Duration.ofSeconds(10);
    /** A part size so small that every input of a few lines is read in several parts. */

    /**
     * Whatever the bytes: a mesh whose corners name its own vertices and normals, or the reader's
     * own errors, located in the OBJ file; the same when the file is read in small parts; never a hang.
     */
    @FuzzTest(maxDuration = "60s")
    void anyBytesGiveAMeshOrLocatedErrors(byte[] bytes) throws SceneException {
        if (System.getenv("JAZZER_FUZZ") != null) {
            check(bytes); // while fuzzing, a thread per input would slow the search a hundredfold
        } else {
            assertTimeoutPreemptively(TIME_LIMIT, () -> check(bytes));
        }
    }

    private static void check(byte[] bytes) throws SceneException {
        SourceText source = new SourceText("fuzz.obj", bytes);
        ObjMesh mesh;
        try {
            mesh = ObjReader.read(source);
        } catch (SceneException e) {
            assertThat(e.errors()).isNotEmpty().hasSizeLessThanOrEqualTo(SceneException.MAX_ERRORS + 1);
            for (SceneError error : e.errors()) {
                assertThat(error.file()).isEqualTo("fuzz.obj");
                assertThat(error.line()).isPositive();
                assertThat(error.column()).isPositive();
                assertThat(error.message()).isNotBlank();
                assertThat(error.format()).startsWith("fuzz.obj:" + error.line() + ":" + error.column() + ": error: ");
            }
            return;
        }
        int vertices = mesh.vertices().length / 3;
        int normals = mesh.normals().length / 3;
        for (int c = 0; c < 3 * mesh.count(); c++) {
            assertThat(mesh.corners()[c]).isBetween(0, vertices - 1);
            assertThat(mesh.cornerNormals()[c]).isBetween(-1, normals - 1);
        }
    }
}
