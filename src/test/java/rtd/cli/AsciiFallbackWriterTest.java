package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.parallel.Isolated;

// it sets the system properties that every run of the command reads its streams' encoding from
@Isolated
@DisplayName("rtd's text in an encoding that lacks its signs")
class AsciiFallbackWriterTest {

    private static final String TEXT = "1920 × 1080: x' = x − w/2, a = R·R, t ≥ 0, floor(255·c + ½), 45°, Grüße 😀";

    private static String written(Charset charset) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintWriter writer = StandardStreams.printWriter(bytes, charset);
        writer.print(TEXT);
        writer.print('≤');
        writer.print(new char[] {'→', '∞'});
        writer.flush();
        return bytes.toString(charset);
    }

    @Test
    void asciiGetsEachSignAsAKeyboardWritesItAndAQuestionMarkForAnyOtherLetter() {
        assertThat(written(StandardCharsets.US_ASCII)).isEqualTo(
                "1920 x 1080: x' = x - w/2, a = R*R, t >= 0, floor(255*c + 1/2), 45 degrees, Gr??e ?<=->inf");
    }

    @Test
    void latin1KeepsTheSignsItHasAndSpellsOutTheOthers() {
        assertThat(written(StandardCharsets.ISO_8859_1)).isEqualTo(
                "1920 × 1080: x' = x - w/2, a = R·R, t >= 0, floor(255·c + ½), 45°, Grüße ?<=->inf");
    }

    @Test
    void utf8IsWrittenAsItIs() {
        assertThat(written(StandardCharsets.UTF_8)).isEqualTo(TEXT + "≤→∞");
    }

    /** Every sign that rtd's own text holds (the string literals of its sources) has a plain spelling. */
    @Test
    void everySignInRtdsOwnTextHasAPlainSpelling() throws IOException {
        Pattern literal = Pattern.compile("\"(?:[^\"\\\\\n]|\\\\.)*\"");
        Set<Character> signs = new TreeSet<>();
        try (Stream<Path> files = Files.walk(Path.of("src", "main", "java"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                Matcher matcher = literal.matcher(unescaped(Files.readString(file)));
                while (matcher.find()) {
                    // U+FFFD is compared with, never written: the mark of a byte an encoding has no letter for
                    matcher.group().chars().filter(c -> c > 127 && c != 0xFFFD).forEach(c -> signs.add((char) c));
                }
            }
        }
        assertThat(signs).contains('×', '−', '·', 'θ', '…'); // '…' is written as \u2026 in SourceText
        for (char sign : signs) {
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            PrintWriter writer = StandardStreams.printWriter(bytes, StandardCharsets.US_ASCII);
            writer.print(sign);
            writer.flush();
            assertThat(bytes.toString(StandardCharsets.US_ASCII)).as("'%s' (U+%04X)", sign, (int) sign).doesNotContain("?");
        }
    }

    /** The text with each {@code \\uXXXX} escape turned into its character, as javac reads it. */
    private static String unescaped(String source) {
        return Pattern.compile("\\\\u+([0-9a-fA-F]{4})").matcher(source)
                .replaceAll(m -> Matcher.quoteReplacement(String.valueOf((char) Integer.parseInt(m.group(1), 16))));
    }

    @Test
    void theEncodingIsTheStreamsOwnPropertyOrTheDefault() {
        String system = System.getProperty("native.encoding");
        System.setProperty("native.encoding", "UTF-16BE");
        try {
            assertThat(StandardStreams.encodingOf("rtd-no-such-stream")).isEqualTo(StandardCharsets.UTF_16BE);
            System.clearProperty("native.encoding");
            assertThat(StandardStreams.encodingOf("rtd-no-such-stream")).isEqualTo(Charset.defaultCharset());
        } finally {
            if (system != null) {
                System.setProperty("native.encoding", system);
            }
        }
        System.setProperty("rtd-test-stream.encoding", "ISO-8859-1");
        System.setProperty("sun.rtd-test-stream.encoding", "UTF-16");
        try {
            assertThat(StandardStreams.encodingOf("rtd-test-stream")).isEqualTo(StandardCharsets.ISO_8859_1);
            System.setProperty("rtd-test-stream.encoding", "no-such-charset");
            assertThat(StandardStreams.encodingOf("rtd-test-stream")).isEqualTo(StandardCharsets.UTF_16);
        } finally {
            System.clearProperty("rtd-test-stream.encoding");
            System.clearProperty("sun.rtd-test-stream.encoding");
        }
    }
}
