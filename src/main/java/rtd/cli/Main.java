package rtd.cli;

/** Starts rtd from {@code java -jar rtd.jar}; see {@link RtdCommand}. */
public final class Main {

    private Main() {
    }

    /** Runs the command and exits with its code: 0 done, 1 scene or file error, 2 misuse. */
    public static void main(String[] args) {
        System.exit(RtdCommand.commandLine().execute(args));
    }
}
