package rtd.cli;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Optional;
import picocli.CommandLine;

/** Runs rtd in this JVM with standard input and output of the test's own making. */
record StreamRun(int exitCode, byte[] out, String err) {

    static StreamRun run(byte[] stdin, boolean outIsTerminal, String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        StandardStreams streams = new StandardStreams(new ByteArrayInputStream(stdin), Optional.empty(), false, out,
                outIsTerminal);
        StringWriter err = new StringWriter();
        CommandLine commandLine = RtdCommand.commandLine(streams);
        commandLine.setOut(new PrintWriter(new StringWriter(), true));
        commandLine.setErr(new PrintWriter(err, true));
        int exitCode = commandLine.execute(args);
        return new StreamRun(exitCode, out.toByteArray(), err.toString());
    }
}
