package rtd.cli;

import rtd.io.ImageFormat;

/** Starts rtd from {@code java -jar rtd.jar}; see {@link RtdCommand}. */
public final class Main {

    private Main() {
    }

    /** Runs the command and exits with its code: 0 done, 1 scene or file error, 2 misuse. */
    public static void main(String[] args) {
        WarmUp.start(ImageFormat.PNG); // the usual format, warmed while picocli starts and the scene is read
        System.exit(RtdCommand.commandLine().execute(args));
    }
}
