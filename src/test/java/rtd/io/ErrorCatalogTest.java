package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * docs/errors.md says what rtd says: each example scene there gives exactly the message shown under
 * it. An {@code obj} block just before a scene is saved beside it under the name it gives. A scene
 * block is saved as UTF-8 with LF line ends, unless its fence names another form after
 * {@code scene}: {@code latin1}, {@code windows-1252}, {@code utf-16le-bom} or {@code cr} (lines
 * ended by a CR alone), for the examples of files that old or foreign editors write.
 */
@DisplayName("The catalogue of messages in docs/errors.md")
class ErrorCatalogTest {

    private static final Pattern EXAMPLE = Pattern.compile(
            "(?:```obj (\\S+)\\n(.*?)```\\s*)?```scene(?: (\\S+))?\\n(.*?)```\\s*```text\\n(.*?)```", Pattern.DOTALL);

    static Stream<Arguments> examples() throws IOException {
        String doc = Files.readString(Path.of("docs", "errors.md"));
        List<Arguments> examples = new ArrayList<>();
        Matcher matcher = EXAMPLE.matcher(doc);
        while (matcher.find()) {
            examples.add(Arguments.of(matcher.group(5).lines().findFirst().orElse(""), matcher.group(4), matcher.group(3),
                    matcher.group(5), matcher.group(1), matcher.group(2)));
        }
        return examples.stream();
    }

    /** The bytes of a scene block in the form its fence names. */
    private static byte[] bytes(String scene, String form) {
        if (form == null) {
            return scene.getBytes(StandardCharsets.UTF_8);
        }
        return switch (form) {
            case "latin1" -> scene.getBytes(StandardCharsets.ISO_8859_1);
            case "windows-1252" -> scene.getBytes(Charset.forName("windows-1252"));
            case "utf-16le-bom" -> ("\uFEFF" + scene).getBytes(StandardCharsets.UTF_16LE);
            case "cr" -> scene.replace('\n', '\r').getBytes(StandardCharsets.UTF_8);
            default -> throw new IllegalArgumentException("unknown form of a scene block: " + form);
        };
    }

    @Test
    void holdsAnExampleForEveryKindOfSceneMistake() throws IOException {
        assertThat(examples()).hasSizeGreaterThanOrEqualTo(74);
    }

    @Test
    void showsNoJavaClassNameAnywhere() throws IOException {
        String doc = Files.readString(Path.of("docs", "errors.md"));
        assertThat(doc).doesNotContainPattern("\\b\\w*(Exception|Error)\\b(?!:)")
                .doesNotContainPattern("\\bjava\\.[a-z]+\\.").doesNotContainPattern("\\b(rtd|sun)\\.[a-z]+\\.[A-Z]");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("examples")
    void showsTheMessageThatRtdGives(String firstLine, String scene, String form, String message, String objName, String obj,
            @TempDir Path folder) throws IOException, SceneException {
        if (objName != null) {
            Files.writeString(folder.resolve(objName), obj);
        }
        byte[] bytes = bytes(scene, form);
        if (firstLine.contains(": warning: ")) { // a slip that is no mistake: the scene reads, and warns
            List<SceneError> warnings = new ArrayList<>();
            SceneIO.parseScene("scene.txt", bytes, folder, warnings);
            assertThat(warnings.stream().map(SceneError::formatAsWarning).collect(Collectors.joining()).strip())
                    .isEqualTo(message.strip());
            return;
        }
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt", bytes, folder, null));
        assertThat(e).as("a SceneException").isNotNull();
        assertThat(e.errors()).hasSize(1);
        assertThat(e.errors().get(0).format().strip()).isEqualTo(message.strip());
    }
}
