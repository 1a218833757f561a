package rtd.pov;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.io.ClockedScene;
import rtd.io.SceneException;
import rtd.io.SceneFile;

/** Each kind of expression in POV-Ray's words, the strings worked out by hand. */
@DisplayName("An expression written for POV-Ray")
class PovExpressionTest {

    /** The x of a sphere's centre written as {@code x}, read and written back for POV-Ray. */
    private static String pov(String lets, String x) throws SceneException {
        ClockedScene clocked = read(lets, x);
        return PovExpression.of(clocked.of(clocked.scene().objects().get(0)).of("centre", 0));
    }

    /** {@code lets}, then a sphere whose centre's x is written as {@code x}, read with its clock's expressions. */
    private static ClockedScene read(String lets, String x) throws SceneException {
        String text = lets + "orthographic_camera:(0|0|10):(0|0|-1):(20)\nsphere:(" + x + "|0|0):(1):(255|0|0)\n";
        return SceneFile.of("t.txt", text.getBytes(StandardCharsets.UTF_8), Path.of("")).withClock(0);
    }

    private static String pov(String x) throws SceneException {
        return pov("", x);
    }

    @Test
    void theClockAndPiAreWrittenAsPovRaysOwn() throws SceneException {
        assertThat(pov("clock")).isEqualTo("clock");
        assertThat(pov("pi*clock")).isEqualTo("pi * clock");
    }

    @Test
    void aNumberIsWrittenInItsShortestPlainDecimal() throws SceneException {
        assertThat(pov("0.1 + 2e3*clock + 1e-5")).isEqualTo("0.1 + 2000 * clock + 0.00001");
    }

    @Test
    void sumsAndProductsKeepTheirOrderWithParenthesesOnlyWhereNeeded() throws SceneException {
        assertThat(pov("1 + 2*clock - 3")).isEqualTo("1 + 2 * clock - 3");
        assertThat(pov("(1 + clock)*2")).isEqualTo("(1 + clock) * 2");
        assertThat(pov("1 - (clock - 2)")).isEqualTo("1 - (clock - 2)");
        assertThat(pov("1/(2 + clock)")).isEqualTo("1 / (2 + clock)");
        assertThat(pov("1/2*clock")).isEqualTo("1 / 2 * clock");
    }

    @Test
    void aMinusSignIsInParenthesesUnlessItComesFirst() throws SceneException {
        assertThat(pov("-clock + 1")).isEqualTo("-clock + 1");
        assertThat(pov("2 * -clock")).isEqualTo("2 * (-clock)");
        assertThat(pov("2 - -clock")).isEqualTo("2 - (-clock)");
        assertThat(pov("-(clock + 1)")).isEqualTo("-(clock + 1)");
    }

    @Test
    void aPowerIsPowAndBindsTighterThanAMinusSign() throws SceneException {
        assertThat(pov("clock^2")).isEqualTo("pow(clock, 2)");
        assertThat(pov("2^clock^2")).isEqualTo("pow(2, pow(clock, 2))");
        assertThat(pov("-clock^2")).isEqualTo("-pow(clock, 2)");
    }

    @Test
    void sinCosAndTanTakeDegreesSoTheirArgumentGoesThroughRadians() throws SceneException {
        assertThat(pov("sin(360*clock)")).isEqualTo("sin(radians(360 * clock))");
        assertThat(pov("cos(clock)")).isEqualTo("cos(radians(clock))");
        assertThat(pov("tan(clock)")).isEqualTo("tan(radians(clock))");
    }

    @Test
    void asinAcosAtanAndAtan2AnswerInDegrees() throws SceneException {
        assertThat(pov("asin(clock)")).isEqualTo("degrees(asin(clock))");
        assertThat(pov("acos(clock)")).isEqualTo("degrees(acos(clock))");
        assertThat(pov("atan(clock)")).isEqualTo("degrees(atan(clock))");
        assertThat(pov("atan2(clock, 1)")).isEqualTo("degrees(atan2(clock, 1))");
    }

    @Test
    void sqrtAbsFloorMinAndMaxArePovRaysOwn() throws SceneException {
        assertThat(pov("sqrt(clock) + abs(clock) + floor(clock)")).isEqualTo("sqrt(clock) + abs(clock) + floor(clock)");
        assertThat(pov("min(clock, 1) * max(2, clock)")).isEqualTo("min(clock, 1) * max(2, clock)");
    }

    /** The {@code #declare}s the export writes for the x of the sphere's centre written as {@code x}. */
    private static String declarations(String lets, String x) throws SceneException {
        return new PovClock(read(lets, x)).declarations();
    }

    @Test
    void aLetsNameIsWrittenAsItsDeclaredIdentifierAndDeclaredOnceAfterTheNamesItUses() throws SceneException {
        String lets = "let:(angle):(360*clock)\nlet:(shift):(clock + 1)\nlet:(size):(3)\nlet:(twice):(shift + shift)\n";
        assertThat(pov(lets, "size*sin(angle)")).isEqualTo("Rtd_size * sin(radians(Rtd_angle))");
        assertThat(pov(lets, "2*shift")).isEqualTo("2 * Rtd_shift");
        assertThat(declarations(lets, "size*sin(angle)")).isEqualTo("#declare Rtd_size = 3;\n#declare Rtd_angle = 360 * clock;\n");
        assertThat(declarations(lets, "twice*twice")).isEqualTo("#declare Rtd_shift = clock + 1;\n"
                + "#declare Rtd_twice = Rtd_shift + Rtd_shift;\n");
    }

    /** Each name is written once, so a chain of names that doubles at every line stays as long as the chain. */
    @Test
    void aChainOfLetsThatDoublesAtEveryLineIsWrittenOnceALine() throws SceneException {
        StringBuilder lets = new StringBuilder("let:(a0):(clock)\n");
        for (int i = 1; i <= 16; i++) {
            lets.append("let:(a").append(i).append("):(a").append(i - 1).append(" + a").append(i - 1).append(")\n");
        }
        String declared = declarations(lets.toString(), "a16");
        assertThat(declared.lines()).hasSize(17);
        assertThat(declared).endsWith("#declare Rtd_a16 = Rtd_a15 + Rtd_a15;\n");
    }

    @Test
    void aLetsPlainNumberIsDeclaredAsTheFloatItIs() throws SceneException {
        String lets = "let:(low):(-2)\nlet:(tenth):(0.1)\n";
        assertThat(pov(lets, "clock * low")).isEqualTo("clock * Rtd_low");
        assertThat(declarations(lets, "clock * low + tenth")).isEqualTo("#declare Rtd_low = -2;\n#declare Rtd_tenth = 0.1;\n");
    }
}
