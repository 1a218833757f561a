package rtd.cli;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Standard input and output as bytes, for {@code -} (the scene from standard input) and
 * {@code -o -} (the picture to standard output), and whether each is a terminal. Tests give
 * their own.
 *
 * @param in            standard input
 * @param inPath        a name that reads standard input as a file ({@code /dev/stdin}), if the
 *                      system has one: read through it, a scene is checked as it arrives, so that
 *                      an endless stream of bytes that are no text ends at once
 * @param inIsTerminal  whether a person types the scene
 * @param out           standard output, unbuffered
 * @param outIsTerminal whether standard output is a terminal, which gets no picture
 */
record StandardStreams(InputStream in, Optional<Path> inPath, boolean inIsTerminal, OutputStream out,
        boolean outIsTerminal) {

    /** The process's own. */
    static StandardStreams system() {
        Path devStdin = Path.of("/dev/stdin");
        return new StandardStreams(System.in, Files.exists(devStdin) ? Optional.of(devStdin) : Optional.empty(),
                Terminal.stdinIsTerminal(), new FileOutputStream(FileDescriptor.out), Terminal.stdoutIsTerminal());
    }
}
