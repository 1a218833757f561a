package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Every kind of mistake in a scene file gets its own message at the right line and column. */
@DisplayName("Mistakes in a scene file")
class SceneErrorsTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";

    static SceneException errorsOf(String text) {
        return errorsOf(text.getBytes(StandardCharsets.UTF_8));
    }

    static SceneException errorsOf(byte[] bytes) {
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt", bytes, Path.of(""), null));
        assertThat(e).as("a SceneException").isNotNull();
        return e;
    }

    static Stream<Arguments> mistakes() {
        return Stream.of(
                Arguments.of("an unknown keyword", CAMERA + "spere:(3|8|-1):(2):(0|127|255)", 2, 1,
                        "unknown statement 'spere'", "did you mean 'sphere'?"),
                Arguments.of("a keyword in the wrong case", CAMERA + "Sphere:(3|8|-1):(2):(0|127|255)", 2, 1,
                        "unknown statement 'Sphere'", "did you mean 'sphere'?"),
                Arguments.of("a line that starts with no keyword", CAMERA + "(3|8|-1)", 2, 1,
                        "expected a statement ('ambient', 'orthographic_camera', 'perspective_camera', 'sphere', 'plane', 'triangle', 'box', 'mesh', 'light', 'material', 'cylinder', 'cone', 'area_light', 'pattern', 'transform' or 'let'), found '('", null),
                Arguments.of("a missing ':'", CAMERA + "sphere(3|8|-1):(2):(0|127|255)", 2, 7,
                        "expected ':' before the centre of 'sphere', found '('", "write it as sphere:(x|y|z):(r):(R|G|B)[:(material)][:(transform)]"),
                Arguments.of("a missing '('", CAMERA + "sphere:3|8|-1):(2):(0|127|255)", 2, 8,
                        "expected '(' to start the centre of 'sphere', found '3'", null),
                Arguments.of("a missing ')'", CAMERA + "sphere:(3|8|-1:(2):(0|127|255)", 2, 15,
                        "expected '|' or ')' after a number in the centre of 'sphere', found ':'", null),
                Arguments.of("a group too few", CAMERA + "sphere:(3|8|-1):(2)", 2, 20,
                        "expected ':' before the colour of 'sphere', found the end of the line", null),
                Arguments.of("a group too many", CAMERA + "sphere:(3|8|-1):(2):(0|127|255):(glass):(lift):(1)", 2, 47,
                        "too many groups: 'sphere' takes 3, or up to 5 with a material and a transform", null),
                Arguments.of("a number too few", CAMERA + "sphere:(3|8):(2):(0|127|255)", 2, 8,
                        "too few numbers in the centre of 'sphere': it takes 3 numbers (x|y|z), found 2", null),
                Arguments.of("a number too many", CAMERA + "sphere:(3|8|-1|4):(2):(0|127|255)", 2, 16,
                        "too many numbers in the centre of 'sphere': it takes 3 numbers (x|y|z)", null),
                Arguments.of("an empty group", CAMERA + "sphere:(3|8|-1):():(0|127|255)", 2, 17,
                        "empty group: the radius of 'sphere' needs 1 number (r)", null),
                Arguments.of("an empty number", CAMERA + "sphere:(3||-1):(2):(0|127|255)", 2, 11,
                        "expected a number, found '|'", null),
                Arguments.of("a word for a number", CAMERA + "sphere:(3|eight|-1):(2):(0|127|255)", 2, 11,
                        "expected a number, found 'eight'", "numbers are written like 3 or -0.5 or .5 or 1. or 2e3"),
                Arguments.of("a typographic minus", CAMERA + "sphere:(3|8|\u22121):(2):(0|127|255)", 2, 13,
                        "expected a number, found '\u22121'", "'\u2212' is a typographic minus sign (U+2212); type the plain '-' instead"),
                Arguments.of("text after the statement", CAMERA + "sphere:(3|8|-1):(2):(0|127|255) red", 2, 33,
                        "expected the end of the line after the statement, found 'red'", "a comment after a statement starts with //"),
                Arguments.of("NaN", CAMERA + "sphere:(NaN|8|-1):(2):(0|127|255)", 2, 9,
                        "the x of the centre must be a finite number, found NaN", null),
                Arguments.of("Infinity", CAMERA + "sphere:(3|-Infinity|-1):(2):(0|127|255)", 2, 11,
                        "the y of the centre must be a finite number, found -Infinity", null),
                Arguments.of("a number too large for a float", CAMERA + "sphere:(3|8|1e40):(2):(0|127|255)", 2, 13,
                        "the z of the centre must be a finite number, found 1e40, which is too large for a float",
                        "a float holds numbers up to about 3.4e38"),
                Arguments.of("a negative radius", CAMERA + "sphere:(3|8|-1):(-1):(0|127|255)", 2, 18,
                        "the radius must be greater than 0, found -1", null),
                Arguments.of("a zero radius", CAMERA + "sphere:(3|8|-1):(0):(0|127|255)", 2, 18,
                        "the radius must be greater than 0, found 0", null),
                Arguments.of("a zero zoom", "orthographic_camera:(0|0|20):(0|0|-1):(0)", 1, 40,
                        "the zoom must be greater than 0, found 0", null),
                Arguments.of("a negative zoom", "orthographic_camera:(0|0|20):(0|0|-1):(-5)", 1, 40,
                        "the zoom must be greater than 0, found -5", null),
                Arguments.of("a zero view direction", "orthographic_camera:(0|0|20):(0|-0|0.0):(50)", 1, 31,
                        "the view direction must not be zero, found (0|-0|0.0)", "the camera looks along it; (0|0|-1) looks into the screen"),
                Arguments.of("a view direction too short for float", "orthographic_camera:(0|0|20):(0|0|-1e-30):(50)", 1, 31,
                        "the view direction (0|0|-1e-30) is too short to compute with in float", null),
                Arguments.of("a colour channel that is not whole", CAMERA + "sphere:(3|8|-1):(2):(0|127.5|255)", 2, 24,
                        "the green channel must be a whole number from 0 to 255, found 127.5", null),
                Arguments.of("a colour channel above 255", CAMERA + "ambient:(256|0|0)", 2, 10,
                        "the red channel must be a whole number from 0 to 255, found 256", null),
                Arguments.of("a negative colour channel", CAMERA + "sphere:(3|8|-1):(2):(0|0|-1)", 2, 26,
                        "the blue channel must be a whole number from 0 to 255, found -1", null),
                Arguments.of("a second camera", CAMERA + "sphere:(3|8|-1):(2):(0|127|255)\n" + CAMERA, 3, 1,
                        "a second camera: a scene has one", "the first camera is at line 1"),
                Arguments.of("a second ambient", "ambient:(1|2|3)\n" + CAMERA + "  ambient:(1|2|3)", 3, 3,
                        "a second 'ambient': a scene has one background colour", "the first 'ambient' is at line 1"),
                Arguments.of("no camera", "ambient:(1|2|3)\nsphere:(3|8|-1):(2):(0|127|255)\n", 1, 1,
                        "the scene has no camera", "add a line such as orthographic_camera:(0|0|20):(0|0|-1):(50)"),
                Arguments.of("an empty file", "", 1, 1,
                        "the scene is empty: it has no statements, only blanks and comments", null),
                Arguments.of("only comments and blanks", "// nothing\n\n   \t\n// here\n", 1, 1,
                        "the scene is empty: it has no statements, only blanks and comments", null));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("mistakes")
    void getsAMessageAtItsLineAndColumn(String mistake, String text, int line, int column, String message, String help) {
        List<SceneError> errors = errorsOf(text).errors();
        assertThat(errors).hasSize(1);
        SceneError error = errors.get(0);
        assertThat(error.message()).isEqualTo(message);
        assertThat(error.line()).as("line").isEqualTo(line);
        assertThat(error.column()).as("column").isEqualTo(column);
        assertThat(error.file()).isEqualTo("scene.txt");
        if (help != null) {
            assertThat(error.help()).isEqualTo(help);
        }
    }

    @Test
    void aFileThatIsNotTextIsSaidToBeSo() {
        byte[] png = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 0, 0};
        SceneError error = errorsOf(png).errors().get(0);
        assertThat(error.message()).startsWith("this is not a text file: found ");
        assertThat(error.format()).doesNotContain(" | ");
        byte[] latin1 = "// Kugel f\u00fcr die Szene\n".getBytes(StandardCharsets.ISO_8859_1);
        SceneError notUtf8 = errorsOf(latin1).errors().get(0);
        assertThat(notUtf8.message()).isEqualTo(
                "the file is not UTF-8 but looks like Latin-1 (ISO-8859-1) or Windows-1252: found byte 0xFC, which is '\u00fc' there");
        assertThat(notUtf8.line()).isEqualTo(1);
        assertThat(notUtf8.column()).isEqualTo(11);
    }

    @Test
    void everyMistakeInTheFileIsReportedNotOnlyTheFirst() {
        SceneException e = errorsOf(CAMERA + "spere:(1|2|3):(1):(0|0|0)\nsphere:(1|2|3):(0):(0|0|0)\n\nsphere:(1|2):(1):(0|0|0)\n");
        assertThat(e.errors()).extracting(SceneError::line).containsExactly(2, 3, 5);
        assertThat(e.report()).contains("3 errors");
    }

    @Test
    void afterTwentyErrorsTheReaderStopsAndSaysSo() {
        SceneException e = errorsOf(CAMERA + "oops\n".repeat(100));
        assertThat(e.errors()).hasSize(SceneException.MAX_ERRORS);
        assertThat(e.report()).endsWith("20 errors shown; the file has more\n");
    }

    @Test
    void theReportShowsTheLineWithACaretUnderTheColumn() {
        String report = errorsOf(CAMERA + "\tsphere:(3|8|-1):(0):(0|127|255)").report();
        assertThat(report).isEqualTo("""
                scene.txt:2:19: error: the radius must be greater than 0, found 0
                 2 | \tsphere:(3|8|-1):(0):(0|127|255)
                   | \t                 ^
                   = help: a radius of 0 leaves nothing to see; give a number greater than 0, such as 1

                1 error
                """);
    }

    @Test
    void columnsCountCharactersNotBytes() {
        SceneError error = errorsOf(CAMERA + "sphere:(3|8|-1):(2):(0|0|0) // Kugel \u00fcber\u00e4ll x\nsph\u00e4re:(1|2|3):(1):(0|0|0)")
                .errors().get(0);
        assertThat(error.line()).isEqualTo(3);
        assertThat(error.column()).isEqualTo(1);
        assertThat(error.message()).isEqualTo("unknown statement 'sph'");
    }
}
