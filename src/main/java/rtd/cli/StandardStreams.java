package rtd.cli;

import java.io.File;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.Charset;
import java.nio.charset.CharsetEncoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * Standard input and output as bytes, for the scene {@code -} and {@code -o -}, and whether each is a terminal. A
 * terminal whose encoding lacks the signs of rtd's text ({@code 1920 × 1080}) gets them in plain ASCII, else {@code ?}.
 * {@code inPath} is standard input as a file ({@code /dev/stdin}) where there is one: a scene read through it is
 * checked as it arrives, so that an endless stream of non-text ends at once.
 */
record StandardStreams(InputStream in, Optional<Path> inPath, boolean inIsTerminal, OutputStream out,
        boolean outIsTerminal) {

    private static final Map<Character, String> PLAIN = Map.ofEntries(
            Map.entry('×', "x"), Map.entry('−', "-"), Map.entry('·', "*"), Map.entry('…', "..."),
            Map.entry('≥', ">="), Map.entry('≤', "<="), Map.entry('√', "sqrt"), Map.entry('→', "->"),
            Map.entry('²', "^2"), Map.entry('⊙', "*"), Map.entry('∞', "inf"), Map.entry('°', " degrees"),
            Map.entry('ε', "eps"), Map.entry('½', "1/2"), Map.entry('ö', "oe"), Map.entry('‖', "|"),
            Map.entry('—', "--"), Map.entry('–', "-"), Map.entry('‘', "'"), Map.entry('’', "'"),
            Map.entry('“', "\""), Map.entry('”', "\""), Map.entry('θ', "theta_"), Map.entry('⁻', "^-"),
            Map.entry('¹', "1"));

    static StandardStreams system() {
        Path devStdin = Path.of("/dev/stdin");
        return new StandardStreams(System.in, Files.exists(devStdin) ? Optional.of(devStdin) : Optional.empty(),
                isTerminal(0), new FileOutputStream(FileDescriptor.out), isTerminal(1));
    }

    /** On Linux, whether file descriptor {@code fd} is a terminal device; elsewhere, whether Java sees a console. */
    static boolean isTerminal(int fd) {
        Path link = Path.of("/proc/self/fd/" + fd);
        try {
            String target = Files.readSymbolicLink(link).toString();
            return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
        } catch (IOException | UnsupportedOperationException e) {
            return !Files.exists(link, LinkOption.NOFOLLOW_LINKS) && System.console() != null;
        }
    }

    /** The terminal's width: {@code $COLUMNS}, else {@code stty size}, else 80. It starts a process: call it once. */
    static int columns() {
        String exported = System.getenv("COLUMNS");
        if (exported != null && exported.matches("[1-9][0-9]{0,4}")) {
            return Integer.parseInt(exported);
        }
        try {
            Process stty = new ProcessBuilder("stty", "size").redirectInput(new File("/dev/tty"))
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start();
            String size = new String(stty.getInputStream().readAllBytes(), StandardCharsets.US_ASCII).trim();
            if (stty.waitFor(2, TimeUnit.SECONDS) && size.matches("[0-9]+ [1-9][0-9]*")) {
                return Integer.parseInt(size.substring(size.indexOf(' ') + 1));
            }
        } catch (IOException e) {
            // no stty or no /dev/tty: the usual width
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return 80;
    }

    /** A writer of {@code stream} in {@code charset}, autoflushing as picocli's own; in ASCII where it must be. */
    static PrintWriter printWriter(OutputStream stream, Charset charset) {
        Writer bytes = new OutputStreamWriter(stream, charset);
        CharsetEncoder encoder = charset.newEncoder();
        for (char sign : PLAIN.keySet()) { // a loop, not a stream: no lambda to set up on every run's way
            if (!encoder.canEncode(sign)) {
                return new PrintWriter(new Writer() {
                    @Override
                    public void write(char[] text, int from, int length) throws IOException {
                        for (int i = from; i < from + length; i++) {
                            if (encoder.canEncode(text[i]) || Character.isSurrogate(text[i])) {
                                bytes.write(text[i]);
                            } else {
                                bytes.write(PLAIN.getOrDefault(text[i], "?"));
                            }
                        }
                    }

                    @Override
                    public void flush() throws IOException {
                        bytes.flush();
                    }

                    @Override
                    public void close() throws IOException {
                        bytes.close();
                    }
                }, true);
            }
        }
        return new PrintWriter(bytes, true);
    }

    /** The encoding {@code System.out} (or {@code err}) writes in; a name the JDK does not know is passed over. */
    static Charset encodingOf(String stream) {
        for (String property : new String[] {stream + ".encoding", "sun." + stream + ".encoding", "native.encoding"}) {
            try {
                return Charset.forName(System.getProperty(property));
            } catch (IllegalArgumentException missingOrUnknown) { // null, illegal or unsupported: the next
            }
        }
        return Charset.defaultCharset();
    }
}
