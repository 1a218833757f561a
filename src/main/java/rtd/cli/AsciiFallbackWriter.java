package rtd.cli;

import java.io.FilterWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.Charset;
import java.nio.charset.CharsetEncoder;
import java.nio.charset.IllegalCharsetNameException;
import java.nio.charset.UnsupportedCharsetException;
import java.util.Map;

/**
 * A writer of rtd's text in the terminal's encoding that spells the signs the encoding lacks in plain ASCII.
 * Messages and {@code --explain} write as a student's notes would ({@code 1920 × 1080}, {@code x − w/2},
 * {@code t ≥ 0}); a terminal without such signs (the C locale of many containers, an old Windows code page)
 * gets {@code x}, {@code -}, {@code >=}, and {@code ?} for any other sign it lacks. UTF-8 is written as it is.
 */
final class AsciiFallbackWriter extends FilterWriter {

    /** How each sign of rtd's text is written without it. */
    private static final Map<Character, String> PLAIN = Map.ofEntries(
            Map.entry('×', "x"), Map.entry('−', "-"), Map.entry('·', "*"), Map.entry('…', "..."),
            Map.entry('≥', ">="), Map.entry('≤', "<="), Map.entry('√', "sqrt"), Map.entry('→', "->"),
            Map.entry('²', "^2"), Map.entry('⊙', "*"), Map.entry('∞', "inf"), Map.entry('°', " degrees"),
            Map.entry('ε', "eps"), Map.entry('½', "1/2"), Map.entry('ö', "oe"), Map.entry('‖', "|"),
            Map.entry('—', "--"), Map.entry('–', "-"), Map.entry('‘', "'"), Map.entry('’', "'"),
            Map.entry('“', "\""), Map.entry('”', "\""), Map.entry('θ', "theta_"));

    private final CharsetEncoder encoder;

    private AsciiFallbackWriter(Writer out, CharsetEncoder encoder) {
        super(out);
        this.encoder = encoder;
    }

    /** A writer of {@code stream} in {@code charset}, autoflushing as picocli's own is; plain where it must be. */
    static PrintWriter printWriter(OutputStream stream, Charset charset) {
        Writer bytes = new OutputStreamWriter(stream, charset);
        CharsetEncoder encoder = charset.newEncoder();
        for (char sign : PLAIN.keySet()) { // a loop, not a stream: no lambda to set up on every run's way
            if (!encoder.canEncode(sign)) {
                return new PrintWriter(new AsciiFallbackWriter(bytes, encoder), true);
            }
        }
        return new PrintWriter(bytes, true);
    }

    /**
     * The encoding {@code System.out} (or {@code err}) writes in: {@code stdout.encoding} (Java 19 on), else
     * {@code sun.stdout.encoding} (a Windows console), else {@code native.encoding}, else the default.
     */
    static Charset encodingOf(String stream) {
        for (String property : new String[] {stream + ".encoding", "sun." + stream + ".encoding", "native.encoding"}) {
            String name = System.getProperty(property);
            if (name != null) {
                try {
                    return Charset.forName(name);
                } catch (IllegalCharsetNameException | UnsupportedCharsetException unknown) {
                    // as the JDK itself does with a name it does not know: the next, or the default
                }
            }
        }
        return Charset.defaultCharset();
    }

    @Override
    public void write(int c) throws IOException {
        char sign = (char) c;
        if (encoder.canEncode(sign) || Character.isSurrogate(sign)) {
            out.write(c);
        } else {
            out.write(PLAIN.getOrDefault(sign, "?"));
        }
    }

    @Override
    public void write(char[] text, int from, int length) throws IOException {
        for (int i = from; i < from + length; i++) {
            write(text[i]);
        }
    }

    @Override
    public void write(String text, int from, int length) throws IOException {
        for (int i = from; i < from + length; i++) {
            write(text.charAt(i));
        }
    }
}
