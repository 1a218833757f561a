package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * docs/errors.md says what rtd says: each example scene there gives exactly the message shown under
 * it. An {@code obj} block just before a scene is saved beside it under the name it gives.
 */
@DisplayName("The catalogue of messages in docs/errors.md")
class ErrorCatalogTest {

    private static final Pattern EXAMPLE = Pattern.compile(
            "(?:```obj (\\S+)\\n(.*?)```\\s*)?```scene\\n(.*?)```\\s*```text\\n(.*?)```", Pattern.DOTALL);

    static Stream<Arguments> examples() throws IOException {
        String doc = Files.readString(Path.of("docs", "errors.md"));
        List<Arguments> examples = new ArrayList<>();
        Matcher matcher = EXAMPLE.matcher(doc);
        while (matcher.find()) {
            examples.add(Arguments.of(matcher.group(4).lines().findFirst().orElse(""), matcher.group(3), matcher.group(4),
                    matcher.group(1), matcher.group(2)));
        }
        return examples.stream();
    }

    @Test
    void holdsAnExampleForEveryKindOfSceneMistake() throws IOException {
        assertThat(examples()).hasSizeGreaterThanOrEqualTo(57);
    }

    @Test
    void showsNoJavaClassNameAnywhere() throws IOException {
        String doc = Files.readString(Path.of("docs", "errors.md"));
        assertThat(doc).doesNotContainPattern("\\b\\w*(Exception|Error)\\b(?!:)")
                .doesNotContainPattern("\\bjava\\.[a-z]+\\.").doesNotContainPattern("\\b(rtd|sun)\\.[a-z]+\\.[A-Z]");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("examples")
    void showsTheMessageThatRtdGives(String firstLine, String scene, String message, String objName, String obj,
            @TempDir Path folder) throws IOException {
        if (objName != null) {
            Files.writeString(folder.resolve(objName), obj);
        }
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt", scene, folder));
        assertThat(e).as("a SceneException").isNotNull();
        assertThat(e.errors()).hasSize(1);
        assertThat(e.errors().get(0).format().strip()).isEqualTo(message.strip());
    }
}
