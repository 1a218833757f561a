package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

@DisplayName("Reading numbers straight from bytes")
class FloatParserTest {

    private static float parse(String text) {
        byte[] bytes = text.getBytes(StandardCharsets.US_ASCII);
        return FloatParser.parse(bytes, 0, bytes.length);
    }

    @ParameterizedTest(name = "{0} reads as Float.parseFloat reads it")
    @ValueSource(strings = {"0", "-0", "1", "1.", ".5", "-.5", "+3", "2e3", "2E+3", "1e-3", "3.4028235e38", "1.4e-45",
        "1e-50", "123456789012345678901234567890", "0.1", "0.30000000000000004", "16777217", "9007199254740993",
        "1e10", "1e11", "1e22", "1e23", "0.000000000000000000001", "7.006492321624085e-46", "1.00000017881393432617187499"})
    void readsAsTheJdkReads(String text) {
        assertThat(Float.floatToRawIntBits(parse(text))).isEqualTo(Float.floatToRawIntBits(Float.parseFloat(text)));
    }

    @Test
    void readsAMillionRandomDecimalsAsTheJdkReadsThem() {
        Random random = new Random(42);
        for (int i = 0; i < 1_000_000; i++) {
            StringBuilder text = new StringBuilder(random.nextBoolean() ? "-" : "");
            int digits = 1 + random.nextInt(random.nextInt(10) == 0 ? 25 : 9);
            int point = random.nextInt(digits + 1);
            for (int d = 0; d < digits; d++) {
                if (d == point) {
                    text.append('.');
                }
                text.append((char) ('0' + random.nextInt(10)));
            }
            if (random.nextInt(4) == 0) {
                text.append('e').append(random.nextInt(80) - 40);
            }
            String number = text.toString();
            assertThat(Float.floatToRawIntBits(parse(number))).as(number)
                    .isEqualTo(Float.floatToRawIntBits(Float.parseFloat(number)));
        }
    }

    @Test
    void readsNaNAndInfinitySoThatTheCallerCanRefuseThem() {
        assertThat(parse("NaN")).isNaN();
        assertThat(parse("-Infinity")).isEqualTo(Float.NEGATIVE_INFINITY);
        assertThat(parse("1e40")).isEqualTo(Float.POSITIVE_INFINITY);
    }

    @ParameterizedTest(name = "''{0}'' is not a number")
    @ValueSource(strings = {"", "-", ".", "e3", "1e", "1e+", "1.2.3", "1f", "1d", "0x10", "--1", "1 2", "inf", "nan", "1,5", "Infinityx"})
    void refusesWhatIsNotANumber(String text) {
        assertThatThrownBy(() -> parse(text)).isInstanceOf(NumberFormatException.class);
    }

    /** The number a group's text starts with, and the offset after it: where the reader looks for '|' or ')'. */
    @ParameterizedTest(name = "''{0}'' starts with a number of {1} bytes")
    @CsvSource(delimiter = ';', value = {"12.5|3; 4; 12.5", "-2e3); 4; -2000", "0.25)(; 4; 0.25", "7 |; 1; 7",
        "1.5.3|; 3; 1.5", "+.5:; 3; 0.5"})
    void readsTheNumberATextStartsWithAndWhereItEnds(String text, int end, float value) {
        byte[] bytes = text.getBytes(StandardCharsets.US_ASCII);
        long number = FloatParser.leading(bytes, 0, bytes.length);
        assertThat((int) (number >>> 32)).isEqualTo(end);
        assertThat(Float.intBitsToFloat((int) number)).isEqualTo(value);
    }

    @ParameterizedTest(name = "''{0}'' starts with no number")
    @ValueSource(strings = {"|", "-|", ".)", "1e|", "NaN|", "Infinity)", "x1|"})
    void findsNoNumberAtTheStartOfAText(String text) {
        byte[] bytes = text.getBytes(StandardCharsets.US_ASCII);
        assertThat(FloatParser.leading(bytes, 0, bytes.length)).isEqualTo(-1);
    }
}
