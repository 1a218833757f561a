package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/** A mistake on a line of megabytes prints a few lines, not megabytes; the column stays exact. */
@DisplayName("Mistakes on giant lines")
class GiantLineTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";
    private static final int MEGABYTES = 5 << 20;

    private static String reportOf(String scene) {
        return SceneErrorsTest.errorsOf(scene).report();
    }

    @Test
    void aLineOfGarbageIsQuotedAndShownByItsStartWithAnEllipsis() {
        String report = reportOf(CAMERA + "x".repeat(MEGABYTES) + "\n");
        assertThat(report).hasSizeLessThan(1000)
                .startsWith("scene.txt:2:1: error: unknown statement '" + "x".repeat(60) + "\u2026'\n")
                .contains(" 2 | " + "x".repeat(100) + "\u2026\n   | ^\n");
    }

    @Test
    void blanksBeforeAMistakeAreShownAsAWindowAroundTheColumnWhichStaysExact() {
        String report = reportOf(CAMERA + " ".repeat(MEGABYTES) + "cube:(1)\n");
        int column = MEGABYTES + 1;
        assertThat(report).hasSizeLessThan(1000)
                .startsWith("scene.txt:2:" + column + ": error: unknown statement 'cube'\n")
                // the last 100 characters: near the end of a line the window shows more before the column
                .contains(" 2 | \u2026" + " ".repeat(92) + "cube:(1)\n")
                .contains("   | " + " ".repeat(93) + "^\n");
    }

    @Test
    void aWindowKeepsTheTabsBeforeTheCaretSoThatItLinesUp() {
        SceneError error = new SceneError("scene.txt", 2, 1001, "found 'x'", "y".repeat(990) + "\t".repeat(10) + "x" + "z".repeat(500), null);
        assertThat(error.format()).contains(" 2 | \u2026" + "y".repeat(30) + "\t".repeat(10) + "x" + "z".repeat(59) + "\u2026\n")
                .contains("   | " + " ".repeat(31) + "\t".repeat(10) + "^\n");
    }

    @Test
    void aShortLineIsShownWhole() {
        SceneError error = new SceneError("scene.txt", 1, 3, "m", "ab\tc", null);
        assertThat(error.format()).isEqualTo("scene.txt:1:3: error: m\n 1 | ab\tc\n   |   ^\n");
    }
}
