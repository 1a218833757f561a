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
 * Writes rtd's text in the terminal's encoding, with plain letters in place of the signs it lacks.
 * rtd's messages and {@code --explain} write as a student's notes would ({@code 1920 × 1080},
 * {@code x − w/2}, {@code N·L}, {@code t ≥ 0}); a terminal whose encoding has no such signs (the
 * C locale of many containers, which is ASCII, or an old Windows code page) would show each as a
 * {@code ?}, and the explanation would lose its operators. There they are written as a plain
 * keyboard writes them ({@code x}, {@code -}, {@code *}, {@code >=}), and any other sign the
 * encoding lacks as {@code ?}, as before. An encoding that has them all (UTF-8) is written to as it is.
 */
final class PlainLetters extends FilterWriter {

    /** How each sign of rtd's text is written without it. */
    private static final Map<Character, String> PLAIN = Map.ofEntries(
            Map.entry('×', "x"), Map.entry('−', "-"), Map.entry('·', "*"), Map.entry('…', "..."),
            Map.entry('≥', ">="), Map.entry('≤', "<="), Map.entry('√', "sqrt"), Map.entry('→', "->"),
            Map.entry('²', "^2"), Map.entry('⊙', "*"), Map.entry('∞', "inf"), Map.entry('°', " degrees"),
            Map.entry('ε', "eps"), Map.entry('½', "1/2"), Map.entry('ö', "oe"), Map.entry('‖', "|"),
            Map.entry('—', "--"), Map.entry('–', "-"), Map.entry('‘', "'"), Map.entry('’', "'"),
            Map.entry('“', "\""), Map.entry('”', "\""), Map.entry('θ', "theta_"));

    private final CharsetEncoder encoder;

    private PlainLetters(Writer out, CharsetEncoder encoder) {
        super(out);
        this.encoder = encoder;
    }

    /**
     * A writer of {@code stream} in {@code charset}, autoflushing as picocli's own is; with plain
     * letters for the signs the charset lacks, if it lacks any of them.
     */
    static PrintWriter printWriter(OutputStream stream, Charset charset) {
        Writer bytes = new OutputStreamWriter(stream, charset);
        CharsetEncoder encoder = charset.newEncoder();
        for (char sign : PLAIN.keySet()) { // a loop, not a stream: no lambda to set up on every run's way
            if (!encoder.canEncode(sign)) {
                return new PrintWriter(new PlainLetters(bytes, encoder), true);
            }
        }
        return new PrintWriter(bytes, true);
    }

    /**
     * The encoding that {@code System.out} (or {@code System.err}) writes in: the JDK's
     * {@code stdout.encoding} where it has one (Java 19 on), its older {@code sun.stdout.encoding}
     * (a Windows console), the system's own {@code native.encoding} (Java 17 on; on Java 18 the
     * default is UTF-8 whatever the terminal's), else the default.
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
