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
        String text = lets + "orthographic_camera:(0|0|10):(0|0|-1):(20)\nsphere:(" + x + "|0|0):(1):(255|0|0)\n";
        ClockedScene clocked = SceneFile.of("t.txt", text.getBytes(StandardCharsets.UTF_8), Path.of("")).withClock(0);
        return PovExpression.of(clocked.of(clocked.scene().objects().get(0)).of("centre", 0));
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

    @Test
    void aLetsNameIsWrittenAsItsDefinitionInParenthesesWhereItNeedsThem() throws SceneException {
        String lets = "let:(angle):(360*clock)\nlet:(shift):(clock + 1)\nlet:(size):(3)\n";
        assertThat(pov(lets, "size*sin(angle)")).isEqualTo("3 * sin(radians(360 * clock))");
        assertThat(pov(lets, "2*shift")).isEqualTo("2 * (clock + 1)");
        assertThat(pov(lets, "shift + 1")).isEqualTo("clock + 1 + 1");
    }

    @Test
    void aLetsPlainNumberIsWrittenAsTheFloatItIsAndInParenthesesIfNegative() throws SceneException {
        String lets = "let:(low):(-2)\nlet:(tenth):(0.1)\n";
        assertThat(pov(lets, "clock * low")).isEqualTo("clock * (-2)");
        assertThat(pov(lets, "low + clock")).isEqualTo("-2 + clock");
        assertThat(pov(lets, "tenth * clock")).isEqualTo("0.1 * clock");
    }
}
