package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Collectors;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.IGeometry;
import rtd.scene.Scene;
import rtd.testing.Describe;

/**
 * A scene file read in parts, the parts after the first in parallel, gives what reading it in one go gives: the
 * same objects in file order, the same mistakes and warnings, the same use of the clock.
 */
@DisplayName("Reading a scene file in parts")
class FilePartsTest {

    /** Lines that stand alone, then lines that use the clock or define names, then mistakes. */
    private static final String[] LINES = {
        "sphere:(%d|1|2):(0.5):(10|20|30)",
        "sphere:(%d|1|2):(0.5):(10|20|30):(shiny)",
        "sphere:(%d|0|0):(1):(checks)",
        "box:(%d|0|0):(-1|2|3):(40|50|60):(shiny):(turn)",
        "triangle:(%d|0|0):(1|0|0):(0|1|0):(1|2|3)",
        "sphere:(%d|size|0):(size/2):(1|2|3)",
        "light:(%d|10|10):(255|255|255)",
        "sphere:(%d|0|0):(6000):(1|1|1)",
        "sphere:(%d|0|0):(1):(1|1|1):(later)",
        "",
        "// a comment %d",
        "sphere:(%d|clock|0):(1):(9|9|9)",
        "material:(m%d):(diffuse=0.5)",
        "let:(v%d):(2*size)",
        "sphere:(%d|0|0):(-1):(1|1|1)",
        "spere:(%d|0|0):(1):(1|1|1)",
        "7 sphere:(%d|0|0):(1):(1|1|1)",
        "sphere:(%d|0|0):(1):(1|1|1):(nothing)",
        "/* a comment of %d\nlines */",
        "ambient:(%d|0|0)",
    };
    private static final int ALONE = 11;
    private static final int VALID = 14;
    private static final String TOP = String.join("\n", "ambient:(1|2|3)", "orthographic_camera:(0|0|20):(0|0|-1):(50)",
            "material:(shiny):(specular=0.5|shininess=20)", "pattern:(checks):(checker):(0|0|0):(255|255|255):(turn)",
            "transform:(turn):(rotate_y 30)", "let:(size):(3)") + "\n";

    /** A random file: the definitions on top, {@code count} lines (the last third of any kind), a material. */
    private static String randomFile(long seed, int count, boolean mistakes) {
        Random random = new Random(seed);
        StringBuilder text = new StringBuilder(TOP);
        for (int i = 0; i < count; i++) {
            int kinds = 3 * i < 2 * count ? ALONE : mistakes ? LINES.length : VALID;
            int kind = random.nextInt(4) > 0 ? random.nextInt(5) : random.nextInt(kinds);
            text.append(String.format(LINES[kind], i)).append('\n');
        }
        text.append("material:(later):(reflective=0.5)\n");
        return seed % 3 == 0 ? text.toString().replace("\n", "\r\n") : seed % 3 == 1 ? text.toString()
                : "\uFEFF" + text.toString().replace("\n", "\r");
    }

    private static SceneFile file(String text, int partSize) {
        return SceneFile.of("scene.txt", text.getBytes(StandardCharsets.UTF_8), Path.of("")).inPartsOf(partSize);
    }

    private static String outcome(String text, int partSize) {
        return outcome(file(text, partSize));
    }

    /** Everything a reading of {@code text} at clock 0.5 gives, as text: the scene or its mistakes, its warnings. */
    private static String outcome(SceneFile file) {
        List<SceneError> warnings = new ArrayList<>();
        try {
            Scene scene = file.at(0.5, warnings);
            ClockedScene clocked = file.withClock(0.5);
            return "ambient " + scene.ambient() + "\ncamera " + scene.camera().generateRay(3, 4, 10, 10)
                    + "\nlights " + scene.lights() + "\nclock " + file.usesClock() + " " + clocked.unwritten() + "\n"
                    + scene.objects().stream().map(FilePartsTest::described).collect(Collectors.joining("\n"))
                    + "\nclocked " + clocked.scene().objects().stream().map(o -> clocked.of(o).groups().toString())
                            .collect(Collectors.joining(" "))
                    + "\nwarnings\n" + warnings.stream().map(SceneError::formatAsWarning).collect(Collectors.joining());
        } catch (SceneException e) {
            return "clock " + file.usesClock() + "\n" + e.report();
        }
    }

    /** What an object is, by value: a record as itself, else its kind, box, colour and finish. */
    private static String described(IGeometry object) {
        String text = Describe.object(object);
        return text.contains("@") ? object.kind() + " " + object.bounds() + " " + object.color() + " "
                + object.material() : text;
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void aSceneWithoutMistakesIsTheSameInAnyParts(long seed) {
        String text = randomFile(seed, 300, false);
        String whole = outcome(text, Integer.MAX_VALUE);
        assertThat(whole).startsWith("ambient").contains("Sphere[", "box BoundingBox", "warnings\n");
        for (int partSize : new int[] {1, 57, 400, 3000}) {
            SceneFile file = file(text, partSize);
            assertThat(outcome(file)).as("cut every %d bytes", partSize).isEqualTo(whole);
            assertThat(file.partsJoined > 0 || partSize < TOP.length()).isTrue(); // the names above are in part 0
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void aSceneWithMistakesGivesTheSameMessagesInAnyParts(long seed) {
        String text = randomFile(seed, 200 + 100 * (int) seed, true);
        String whole = outcome(text, Integer.MAX_VALUE);
        assertThat(whole).contains("error:");
        for (int partSize : new int[] {1, 90, 700, 5000}) {
            assertThat(outcome(text, partSize)).as("cut every %d bytes", partSize).isEqualTo(whole);
        }
    }

    @Test
    void linesThatStandAloneAreReadInParallel() throws SceneException {
        String text = TOP + "sphere:(0|0|0):(1):(1|2|3):(shiny)\n".repeat(2000) + "sphere:(0|size|0):(1):(checks)\n";
        SceneFile file = file(text, 4096);
        Scene scene = file.once(null);
        assertThat(file.partsJoined).isGreaterThan(10);
        assertThat(scene.objects()).hasSize(2001);
        assertThat(scene.objects().get(1999).material().specular()).isEqualTo(0.5f);
        assertThat(scene.objects().get(2000).bounds().min().y()).isGreaterThan(1.9f);
    }

    /** A part that defines a name, uses the clock or has a mistake is read again after the parts above it. */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"let:(w):(1)", "material:(m):(diffuse=0.5)", "sphere:(0|clock|0):(1):(1|1|1)",
        "sphere:(0|0|0):(0):(1|1|1)", "7 sphere:(0|0|0):(1):(1|1|1)"})
    void aPartThatDependsOnTheLinesAboveIsReadInOrder(String line) {
        String text = TOP + ("sphere:(0|0|0):(1):(1|2|3)\n".repeat(500) + line + "\n").repeat(4) + "let:(w):(2)\n"
                + "material:(m):(diffuse=0.7)\n";
        String whole = outcome(text, Integer.MAX_VALUE);
        assertThat(outcome(text, 2048)).isEqualTo(whole);
    }

    @Test
    void moreMistakesThanAreShownGiveTheSameFirstOnesAndTheCountOfTheRest() {
        String text = TOP + "sphere:(0|0|0):(1):(1|2|3)\n".repeat(3000) + "sphere:(0|0|0):(-1):(1|2|3)\n".repeat(30)
                + "sphere:(0|0|0):(1):(1|1|1):(unknown)\n";
        String whole = outcome(text, Integer.MAX_VALUE);
        assertThat(whole).contains("scene.txt:3007:", "the file has more").doesNotContain("unknown");
        assertThat(outcome(text, 1000)).isEqualTo(whole);
    }

    /** Cut at every byte: each line a part of its own, a CR LF never split, one giant line one part. */
    @ParameterizedTest(name = "line ends {0}")
    @ValueSource(strings = {"\n", "\r\n", "\r"})
    void aCutAtEachLineBreakKeepsTheLineNumbers(String lineEnd) {
        String text = (TOP + "sphere:(0|0|0):(1):(1|2|3)\nsphere:(1|0|0):(x):(1|2|3)\n\nsphere:(0|0|0):(1):(1|2|3)\n")
                .replace("\n", lineEnd);
        String whole = outcome(text, Integer.MAX_VALUE);
        assertThat(whole).contains("scene.txt:8:");
        assertThat(outcome(text, 1)).isEqualTo(whole);
        String giant = TOP + "sphere:(0|0|0):(1):(1|2|3)" + " ".repeat(100_000) + "// one long line";
        assertThat(outcome(giant, 1024)).isEqualTo(outcome(giant, Integer.MAX_VALUE));
    }

    /** Letters beyond ASCII in a later part keep the line numbers; a byte that is no UTF-8 is found in any part. */
    @Test
    void aByteThatIsNotUtf8IsFoundInAnyPart() {
        String text = TOP + "sphere:(0|0|0):(1):(1|2|3)\n".repeat(300) + "// größer\n" + "sphere:(0|0|0):(x):(1|2|3)\n";
        String whole = outcome(text, Integer.MAX_VALUE);
        assertThat(whole).contains("scene.txt:308:");
        assertThat(outcome(text, 1000)).isEqualTo(whole);
        byte[] bytes = (text + "sphere:(0|0|0):(1):(1|2|3)\n".repeat(300)).getBytes(StandardCharsets.UTF_8);
        bytes[bytes.length - 100] = (byte) 0xFF;
        String notUtf8 = outcome(SceneFile.of("scene.txt", bytes, Path.of("")));
        assertThat(notUtf8).contains("UTF-8");
        assertThat(outcome(SceneFile.of("scene.txt", bytes, Path.of("")).inPartsOf(1000))).isEqualTo(notUtf8);
    }

    @Test
    void partsReadByThreeThreadsGiveTheSameSceneAsOneThread() {
        String text = TOP + "sphere:(0|0|0):(1):(1|2|3):(shiny)\n".repeat(2000)
                + randomFile(4, 2000, false).substring(TOP.length());
        SceneFile three = file(text, 999).onThreads(3);
        String parallel = outcome(three);
        assertThat(three.partsJoined).isGreaterThan(10);
        assertThat(parallel).startsWith("ambient").isEqualTo(outcome(file(text, 999).onThreads(1)));
        assertThat(parallel).isEqualTo(outcome(text, Integer.MAX_VALUE));
    }

    /** With one thread no part is read apart: the whole file is read in order by the thread that asks. */
    @Test
    void aParseOnOneThreadReadsTheFileInOrderOnTheCallingThread() throws SceneException {
        String text = TOP + "sphere:(0|0|0):(1):(1|2|3):(shiny)\n".repeat(2000);
        SceneFile file = file(text, 4096).onThreads(1);
        assertThat(file.once(null).objects()).hasSize(2000);
        assertThat(file.partsJoined).isZero();
    }

    @Test
    void aParseOnNoThreadsIsRefusedAtOnce() {
        assertThatThrownBy(() -> file("ambient:(1|2|3)\n", 4096).onThreads(0))
                .isInstanceOf(IllegalArgumentException.class).hasMessage("threads must be 1 or more, not 0");
    }
}
