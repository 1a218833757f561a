package rtd.testing;

import java.io.PrintWriter;
import java.io.StringWriter;
import picocli.CommandLine;
import rtd.cli.RtdCommand;

/** Runs rtd's command line in this JVM, as {@code java -jar rtd.jar ARGS} would, and keeps its output. */
public final class Cli {

    /** What one run printed, and its exit code. */
    public record Run(int exitCode, String out, String err) {
    }

    private Cli() {
    }

    /** Runs rtd with {@code args}. */
    public static Run run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine commandLine = RtdCommand.commandLine();
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        int exitCode = commandLine.execute(args);
        return new Run(exitCode, out.toString(), err.toString());
    }
}
