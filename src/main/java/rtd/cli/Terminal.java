package rtd.cli;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Whether a standard stream is a terminal, where a person reads it, and how wide that terminal
 * is: a progress line goes only to a terminal, and must fit its width; a picture never goes to one.
 */
final class Terminal {

    /** The width assumed when the terminal does not tell. */
    static final int DEFAULT_COLUMNS = 80;

    private Terminal() {
    }

    /** Whether standard error is a terminal. */
    static boolean stderrIsTerminal() {
        return isTerminal(2);
    }

    /** Whether standard output is a terminal. */
    static boolean stdoutIsTerminal() {
        return isTerminal(1);
    }

    /** Whether standard input is a terminal (a person types the scene, and ends it with Ctrl-D). */
    static boolean stdinIsTerminal() {
        return isTerminal(0);
    }

    /**
     * On Linux, whether file descriptor {@code fd} is a terminal device; elsewhere, whether Java
     * sees a console (which needs standard input and output to be terminals).
     */
    private static boolean isTerminal(int fd) {
        Path link = Path.of("/proc/self/fd/" + fd);
        if (Files.exists(link, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
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
     * The terminal's width in columns: {@code $COLUMNS} if the shell exported it, else what
     * {@code stty size} says of {@code /dev/tty}, else {@value #DEFAULT_COLUMNS}. It starts a
     * process, so call it once, off the main thread.
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
            // no stty or no /dev/tty: assume the usual width
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return DEFAULT_COLUMNS;
    }
}
