package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

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
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** docs/errors.md says what rtd says: each example scene there gives exactly the message shown under it. */
@DisplayName("The catalogue of messages in docs/errors.md")
class ErrorCatalogTest {

    private static final Pattern EXAMPLE = Pattern.compile("```scene\\n(.*?)```\\s*```text\\n(.*?)```", Pattern.DOTALL);

    static Stream<Arguments> examples() throws IOException {
        String doc = Files.readString(Path.of("docs", "errors.md"));
        List<Arguments> examples = new ArrayList<>();
        Matcher matcher = EXAMPLE.matcher(doc);
        while (matcher.find()) {
            examples.add(Arguments.of(matcher.group(2).lines().findFirst().orElse(""), matcher.group(1), matcher.group(2)));
        }
        return examples.stream();
    }

    @Test
    void holdsAnExampleForEveryKindOfSceneMistake() throws IOException {
        assertThat(examples()).hasSizeGreaterThanOrEqualTo(27);
    }

    @Test
    void showsNoJavaClassNameAnywhere() throws IOException {
        String doc = Files.readString(Path.of("docs", "errors.md"));
        assertThat(doc).doesNotContainPattern("\\b\\w*(Exception|Error)\\b(?!:)")
                .doesNotContainPattern("\\bjava\\.[a-z]+\\.").doesNotContainPattern("\\b(rtd|sun)\\.[a-z]+\\.[A-Z]");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("examples")
    void showsTheMessageThatRtdGives(String firstLine, String scene, String message) {
        SceneException e = SceneErrorsTest.errorsOf(scene);
        assertThat(e.errors()).hasSize(1);
        assertThat(e.errors().get(0).format().strip()).isEqualTo(message.strip());
    }
}
