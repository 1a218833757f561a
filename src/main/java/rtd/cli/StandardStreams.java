package rtd.cli;

import java.io.File;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * Standard input and output as bytes, for the scene {@code -} and {@code -o -}, and whether each standard stream
 * is a terminal: a person types the scene there, a picture never goes there, a progress line only there, and fits
 * its width. Tests give their own.
 *
 * @param inPath a name that reads standard input as a file ({@code /dev/stdin}) where the system has one: read
 *               through it, a scene is checked as it arrives, so that an endless stream of non-text ends at once
 * @param out    standard output, unbuffered
 */
record StandardStreams(InputStream in, Optional<Path> inPath, boolean inIsTerminal, OutputStream out,
        boolean outIsTerminal) {

    /** The width assumed when the terminal does not tell. */
    static final int DEFAULT_COLUMNS = 80;

    /** The process's own. */
    static StandardStreams system() {
        Path devStdin = Path.of("/dev/stdin");
        return new StandardStreams(System.in, Files.exists(devStdin) ? Optional.of(devStdin) : Optional.empty(),
                isTerminal(0), new FileOutputStream(FileDescriptor.out), isTerminal(1));
    }

    static boolean stderrIsTerminal() {
        return isTerminal(2);
    }

    /** On Linux, whether file descriptor {@code fd} is a terminal device; elsewhere, whether Java sees a console. */
    private static boolean isTerminal(int fd) {
        Path link = Path.of("/proc/self/fd/" + fd);
        if (Files.exists(link, LinkOption.NOFOLLOW_LINKS)) {
            try {
                String target = Files.readSymbolicLink(link).toString();
                return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
            } catch (IOException | UnsupportedOperationException e) {
                return false;
            }
        }
        return System.console() != null;
    }

    /**
     * The terminal's width: {@code $COLUMNS} if the shell exported it, else what {@code stty size} says of
     * {@code /dev/tty}, else {@value #DEFAULT_COLUMNS}. It starts a process: call it once, off the main thread.
     */
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
        return DEFAULT_COLUMNS;
    }
}
