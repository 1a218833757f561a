package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static rtd.io.SceneErrorsTest.errorsOf;

import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import rtd.scene.Scene;

/** The mistakes people really make get a help line that says what to do. */
@DisplayName("Hints for the mistakes people really make")
class HintsTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";
    private static final String SPHERE = "sphere:(3|8|-1):(2):(0|127|255)\n";

    private static SceneError onlyError(String text) {
        return onlyError(text.getBytes(StandardCharsets.UTF_8));
    }

    private static SceneError onlyError(byte[] bytes) {
        List<SceneError> errors = errorsOf(bytes).errors();
        assertThat(errors).hasSize(1);
        return errors.get(0);
    }

    @Nested
    @DisplayName("Numbers")
    class Numbers {

        @ParameterizedTest(name = "{0} is to be written {1}")
        @CsvSource(delimiter = ';', value = {"2,5;2.5", "-0,5;-0.5", ",5;.5", "1,5e3;1.5e3"})
        void aDecimalCommaIsToldToBeAPoint(String written, String meant) {
            SceneError error = onlyError(CAMERA + "sphere:(3|8|-1):(" + written + "):(0|127|255)");
            assertThat(error.message()).isEqualTo("expected a number, found '" + written + "'");
            assertThat(error.column()).isEqualTo(18);
            assertThat(error.help()).isEqualTo("write decimals with a point: " + meant);
        }

        @Test
        void aDecimalCommaInAMaterialIsToldToBeAPointToo() {
            assertThat(onlyError(CAMERA + "material:(glass):(ior=1,5)").help()).isEqualTo("write decimals with a point: 1.5");
        }

        @ParameterizedTest(name = "in {0}")
        @CsvSource(delimiter = ';', value = {"sphere:(3|8|-1):(2):(0|12,5|255);24;the colour of 'sphere'",
            "area_light:(0|9|0):(2|0|0):(0|0|2):(4,5|4):(255|255|255);37;the samples of 'area_light'"})
        void aDecimalCommaInAGroupOfWholeNumbersIsToldToBeABarNotAPoint(String line, int column, String group) {
            SceneError error = onlyError(CAMERA + line);
            assertThat(error.column()).isEqualTo(column);
            assertThat(error.help()).isEqualTo("in " + group + ", write whole numbers separated by '|', not ','");
        }

        @Test
        void commasBetweenTheNumbersOfAGroupAreToldToBeBars() {
            assertThat(onlyError(CAMERA + "sphere:(3,8,-1):(2):(0|127|255)").help())
                    .isEqualTo("separate the numbers of a group with '|', not ','");
            assertThat(onlyError(CAMERA + "sphere:(3, 8, -1):(2):(0|127|255)").help())
                    .isEqualTo("separate the numbers of a group with '|', not ','");
        }

        @Test
        void theHelpThatListsTheFormsOfNumbersHasNoCommaThatCouldBeADecimalComma() {
            String help = onlyError(CAMERA + "sphere:(3|eight|-1):(2):(0|127|255)").help();
            assertThat(help).isEqualTo("numbers are written like 3 or -0.5 or .5 or 1. or 2e3").doesNotContain(",");
        }
    }

    @Nested
    @DisplayName("Files that are not UTF-8")
    class Encodings {

        @Test
        void aLatin1UmlautIsNamedShownInItsLineAndToldToBeSavedAsUtf8() {
            byte[] latin1 = (CAMERA + "// gr\u00f6\u00dfer\n" + SPHERE).getBytes(StandardCharsets.ISO_8859_1);
            SceneError error = onlyError(latin1);
            assertThat(error.message()).isEqualTo("the file is not UTF-8 but looks like Latin-1 (ISO-8859-1) or "
                    + "Windows-1252: found byte 0xF6, which is '\u00f6' there");
            assertThat(error.line()).isEqualTo(2);
            assertThat(error.column()).isEqualTo(6);
            assertThat(error.sourceLine()).isEqualTo("// gr\u00f6\u00dfer");
            assertThat(error.help()).isEqualTo("save the file as UTF-8");
        }

        @Test
        void aByteThatOnlyWindows1252HasALetterForNamesWindows1252() {
            byte[] cp1252 = (CAMERA + "// 5 \u20ac\n").getBytes(Charset.forName("windows-1252"));
            assertThat(onlyError(cp1252).message())
                    .isEqualTo("the file is not UTF-8 but looks like Windows-1252: found byte 0x80, which is '\u20ac' there");
        }

        @ParameterizedTest(name = "{0}")
        @CsvSource(delimiter = ';', value = {
            "UTF-16LE;true;little-endian, with a byte-order mark;1;found byte 0xFF",
            "UTF-16BE;true;big-endian, with a byte-order mark;1;found byte 0xFE",
            "UTF-16LE;false;little-endian, without a byte-order mark;2;found a NUL byte",
            "UTF-16BE;false;big-endian, without a byte-order mark;1;found a NUL byte"})
        void utf16IsRecognisedWithOrWithoutAByteOrderMarkAndItsFirstBadByteNamed(String charset, boolean mark,
                String form, int column, String found) {
            byte[] bytes = ((mark ? "\uFEFF" : "") + CAMERA + SPHERE).getBytes(Charset.forName(charset));
            SceneError error = onlyError(bytes);
            assertThat(error.message()).isEqualTo("the file is not UTF-8 but looks like UTF-16 (" + form + "): " + found);
            assertThat(error.line()).isEqualTo(1);
            assertThat(error.column()).isEqualTo(column);
            assertThat(error.help()).isEqualTo("save the file as UTF-8");
        }

        @Test
        void theFirstBadByteIsNamedEvenWhenANulByteComesLaterInThePart() {
            byte[] bytes = (CAMERA + "// f\u00fcr\n" + SPHERE + "\u0000").getBytes(StandardCharsets.ISO_8859_1);
            SceneError error = onlyError(bytes);
            assertThat(error.message()).isEqualTo("this is not a text file: found byte 0xFC, which is not UTF-8");
            assertThat(error.line()).isEqualTo(2);
            assertThat(error.column()).isEqualTo(5);
        }

        @Test
        void aLatin1ByteAfterAUtf8ByteOrderMarkIsInTheRightColumn() {
            byte[] text = ("// f\u00fcr\n" + CAMERA).getBytes(StandardCharsets.ISO_8859_1);
            byte[] bytes = new byte[text.length + 3];
            bytes[0] = (byte) 0xEF;
            bytes[1] = (byte) 0xBB;
            bytes[2] = (byte) 0xBF;
            System.arraycopy(text, 0, bytes, 3, text.length);
            SceneError error = onlyError(bytes);
            assertThat(error.line()).isEqualTo(1);
            assertThat(error.column()).isEqualTo(5);
        }
    }

    @Nested
    @DisplayName("Comments as other languages write them")
    class Comments {

        @Test
        void aHashCommentIsToldThatCommentsStartWithSlashes() {
            SceneError error = onlyError(CAMERA + "# the blue sphere\n" + SPHERE);
            assertThat(error.message()).endsWith("found '#'");
            assertThat(error.help()).isEqualTo("comments start with //");
        }

        @Test
        void aHashCommentAfterAStatementIsToldSoToo() {
            assertThat(onlyError(CAMERA + "sphere:(3|8|-1):(2):(0|127|255) # blue").help()).isEqualTo("comments start with //");
        }

        @Test
        void aBlockCommentOfSeveralLinesIsOneMistakeAndTheStatementsInItAreNotRead() {
            SceneError error = onlyError(CAMERA + "/* an old camera:\n" + CAMERA + "and a word */ " + SPHERE);
            assertThat(error.line()).isEqualTo(2);
            assertThat(error.message()).endsWith("found '/*'");
            assertThat(error.help()).isEqualTo("comments start with //");
        }

        @Test
        void theLineAfterABlockCommentOnOneLineIsReadAgain() {
            SceneException e = errorsOf(CAMERA + "/* one line */\nspere:(3|8|-1):(2):(0|127|255)\n");
            assertThat(e.errors()).extracting(SceneError::line).containsExactly(2, 3);
        }

        @Test
        void aBlockCommentOverManyLinesIsOneMistakeAndTheLinesInItAreSkipped() {
            String text = CAMERA + SPHERE.repeat(20) + "/* commented out:\n" + CAMERA + SPHERE.repeat(20) + "*/\nspere:(1|2|3):(1):(0|0|0)\n";
            String source = text;
            String whole = catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt", source)).report();
            assertThat(whole).contains("2 errors");
        }
    }

    @Nested
    @DisplayName("Other words for a statement")
    class Synonyms {

        @ParameterizedTest(name = "{0} suggests {1}")
        @CsvSource(delimiter = ';', quoteCharacter = '"', value = {
            "camera;'orthographic_camera' or 'perspective_camera'", "Cam;'orthographic_camera' or 'perspective_camera'",
            "perspective;'perspective_camera'", "ortho;'orthographic_camera'", "kugel;'sphere'", "ball;'sphere'",
            "bg;'ambient'", "Hintergrund;'ambient'", "colour;'ambient'", "lamp;'light'",
            "lichtquelle;'light'", "floor;'plane'", "cube;'box'", "tri;'triangle'", "obj;'mesh'", "model;'mesh'", "mat;'material'"})
        void aWordThatSharesNoSpellingWithItsKeywordSuggestsIt(String word, String suggested) {
            SceneError error = onlyError(CAMERA + word + ":(3|8|-1):(2):(0|127|255)");
            assertThat(error.message()).isEqualTo("unknown statement '" + word + "'");
            assertThat(error.help()).isEqualTo("did you mean " + suggested + "?");
        }

        @Test
        void aMisspeltKeywordStillSuggestsTheKeyword() {
            assertThat(onlyError(CAMERA + "spehre:(3|8|-1):(2):(0|127|255)").help()).isEqualTo("did you mean 'sphere'?");
        }
    }

    @Nested
    @DisplayName("One statement per line")
    class OneStatementPerLine {

        @Test
        void aSecondStatementOnTheLineIsToldToStartANewLine() {
            SceneError error = onlyError("ambient:(127|255|255) " + CAMERA);
            assertThat(error.column()).isEqualTo(23);
            assertThat(error.help()).isEqualTo("one statement per line: start a new line before 'orthographic_camera'");
        }

        @Test
        void aSecondStatementAfterASemicolonIsToldToStartANewLine() {
            assertThat(onlyError(CAMERA + "sphere:(3|8|-1):(2):(0|127|255);sphere:(1|2|3):(1):(0|0|0)").help())
                    .isEqualTo("one statement per line: start a new line before 'sphere'");
        }

        @Test
        void aSemicolonAtTheEndIsToldToGo() {
            SceneError error = onlyError(CAMERA + "sphere:(3|8|-1):(2):(0|127|255);  // blue");
            assertThat(error.message()).isEqualTo("expected the end of the line after the statement, found ';'");
            assertThat(error.help()).isEqualTo("one statement per line, with nothing after it: remove the ';'");
        }
    }

    @Nested
    @DisplayName("Invisible characters")
    class Invisible {

        @Test
        void aNoBreakSpaceIsNamedInsteadOfShownAsABlank() {
            SceneError error = onlyError(CAMERA + "sphere:(3|8|-1):\u00a0(2):(0|127|255)");
            assertThat(error.message()).isEqualTo("expected '(' to start the radius of 'sphere', found U+00A0 NO-BREAK SPACE");
            assertThat(error.column()).isEqualTo(17);
            assertThat(error.help()).startsWith("U+00A0 looks like a space but is not one: type a plain space instead");
        }

        @Test
        void aNoBreakSpaceAfterANumberIsNamedWhereItStands() {
            SceneError error = onlyError(CAMERA + "sphere:(3|8|-1\u00a0):(2):(0|127|255)");
            assertThat(error.message()).isEqualTo("expected '|' or ')' after a number, found U+00A0 NO-BREAK SPACE");
            assertThat(error.column()).isEqualTo(15);
        }

        @Test
        void aZeroWidthSpaceBeforeANumberIsNamedAndToldToBeDeleted() {
            SceneError error = onlyError(CAMERA + "sphere:(3|8|\u200b-1):(2):(0|127|255)");
            assertThat(error.message()).isEqualTo("expected a number, found U+200B ZERO WIDTH SPACE");
            assertThat(error.help()).startsWith("U+200B cannot be seen but is there: delete it");
        }

        @Test
        void aByteOrderMarkInsideTheFileIsNamedAsOne() {
            SceneError error = onlyError(CAMERA + "\ufeff" + SPHERE);
            assertThat(error.message()).endsWith("found U+FEFF ZERO WIDTH NO-BREAK SPACE (a byte-order mark)");
            assertThat(error.help()).endsWith("delete it");
        }
    }

    @Nested
    @DisplayName("The paper's listing with its line numbers")
    class LineNumbers {

        private final String listing = numbered(List.of("// Die Szene", "ambient:(127|255|255)", CAMERA.strip(), "",
                SPHERE.strip(), "sphere:(-10|1|5):(5):(255|0|0)"));

        private String numbered(List<String> lines) {
            return IntStream.range(0, lines.size()).mapToObj(k -> (k + 1) + " " + lines.get(k) + "\n")
                    .collect(Collectors.joining());
        }

        @Test
        void theNumbersAreOneMistakeAtTheFirstLineNotOnePerLine() {
            SceneError error = onlyError(listing);
            assertThat(error.line()).isEqualTo(1);
            assertThat(error.column()).isEqualTo(1);
            assertThat(error.message()).isEqualTo("the line starts with a line number, '1', as do 5 more lines");
            assertThat(error.help()).isEqualTo("it looks like the lines are numbered, as in the paper's listing: "
                    + "remove the numbers at the start of each line");
        }

        @Test
        void theStatementsAfterTheNumbersAreStillChecked() {
            SceneException e = errorsOf(listing.replace("(5):", "(0):"));
            assertThat(e.errors()).extracting(SceneError::line).containsExactly(1, 6);
        }

        @Test
        void moreNumberedLinesThanTheErrorLimitDoNotStopTheReading() {
            String text = numbered(java.util.Collections.nCopies(100, SPHERE.strip())) + "spere:(1|2|3):(1):(0|0|0)\n";
            SceneException e = errorsOf(CAMERA + text);
            assertThat(e.errors()).extracting(SceneError::line).containsExactly(2, 102);
            assertThat(e.errors().get(0).message()).endsWith("as do 99 more lines");
        }

        @Test
        void aLongNumberedListingIsOneMistakeAtItsFirstLine() {
            String source = listing.repeat(30);
            SceneException e = catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt", source));
            assertThat(e.errors().get(0).line()).isEqualTo(1);
            assertThat(e.errors().get(0).message()).contains("line number");
        }
    }

    @Nested
    @DisplayName("Lines ended by a CR alone")
    class OldMacLineEnds {

        private final String text = CAMERA + "\n// the blue sphere\n" + SPHERE + "sphere:(-10|1|5):(5):(255|0|0)\n";

        @Test
        void aFileWithCrLineEndsReadsAsWithLfLineEnds() throws Exception {
            Scene lf = SceneIO.parseScene("scene.txt", text);
            Scene cr = SceneIO.parseScene("scene.txt", text.replace('\n', '\r'));
            assertThat(cr.objects()).isEqualTo(lf.objects());
            assertThat(cr.camera()).usingRecursiveComparison().isEqualTo(lf.camera());
        }

        @Test
        void aMistakeInALaterLineHasItsLineNumberAndItsLineAlone() {
            SceneError error = onlyError((text + "spere:(1|2|3):(1):(0|0|0)\r" + SPHERE).replace('\n', '\r'));
            assertThat(error.line()).isEqualTo(6);
            assertThat(error.sourceLine()).isEqualTo("spere:(1|2|3):(1):(0|0|0)");
        }

        @Test
        void crLfAndCrAloneMixedCountOneLineEach() {
            SceneError error = onlyError(CAMERA.strip() + "\r\n\r" + SPHERE.strip() + "\r\nspere:(1|2|3):(1):(0|0|0)");
            assertThat(error.line()).isEqualTo(4);
        }

        @Test
        void aLatin1ByteAfterCrLineEndsHasItsLineNumber() {
            SceneError error = onlyError((CAMERA + SPHERE + "// f\u00fcr\n").replace('\n', '\r').getBytes(StandardCharsets.ISO_8859_1));
            assertThat(error.line()).isEqualTo(3);
            assertThat(error.column()).isEqualTo(5);
        }

        @Test
        void aLargeCrFileCountsItsLines() {
            String many = (CAMERA + (SPHERE + "spere:(1|2|3):(1):(0|0|0)\n").repeat(8)).replace('\n', '\r');
            String source = many;
            String whole = catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt", source)).report();
            assertThat(whole).contains(":17:1: error");
        }

        @Test
        void aCrFileFromDiskRendersItsScene(@org.junit.jupiter.api.io.TempDir Path folder) throws Exception {
            Path file = Files.write(folder.resolve("mac.txt"), text.replace('\n', '\r').getBytes(StandardCharsets.UTF_8));
            assertThat(SceneIO.readScene(file).objects()).hasSize(2);
        }
    }
}
