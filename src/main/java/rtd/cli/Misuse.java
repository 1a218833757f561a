package rtd.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.UnmatchedArgumentException;
import rtd.io.Hints;

/**
 * A mistake on the command line found while planning the run, reported as picocli reports one (exit code 2); and how
 * every mistake on the command line is reported: one line, the options it may have meant, and where to read more.
 */
final class Misuse extends RuntimeException {
    private static final long serialVersionUID = 1L;

    Misuse(String message) {
        super(message);
    }

    /** A misuse saying {@code message}, if {@code wrong}. */
    static void refuse(boolean wrong, String message) {
        if (wrong) {
            throw new Misuse(message);
        }
    }

    /** A misuse unless {@code option}, which works on one picture, is given one scene file. */
    static void oneSceneFile(String option, List<Path> scenes) {
        refuse(scenes.size() > 1, option + " works on one scene file, but " + scenes.size()
                + " were given; run rtd once for each");
    }

    /** Reports {@code ex} on the command line's error stream; answers the exit code for a misuse. */
    static int report(ParameterException ex) {
        CommandLine cmd = ex.getCommandLine();
        PrintWriter err = cmd.getErr();
        err.println("rtd: " + ex.getMessage());
        List<String> suggestions = suggestions(ex);
        if (!suggestions.isEmpty()) {
            err.println("Possible solutions: " + String.join(", ", suggestions));
        }
        err.println("Try '" + cmd.getCommandName() + " --help' for more information.");
        err.flush();
        return cmd.getCommandSpec().exitCodeOnInvalidInput();
    }

    /**
     * For an unknown option, the options it may have meant: first the one within a few edits of it ({@code --wdith}:
     * {@code --width}, a swap of two letters that picocli's likeness misses), then picocli's own suggestions.
     */
    private static List<String> suggestions(ParameterException ex) {
        if (!(ex instanceof UnmatchedArgumentException unmatched)) {
            return List.of();
        }
        List<String> picocli = unmatched.getSuggestions();
        List<String> words = unmatched.getUnmatched();
        if (words.isEmpty() || !words.get(0).startsWith("--")) {
            return picocli;
        }
        String nearest = Hints.nearest(words.get(0).split("=", 2)[0].substring(2), ex.getCommandLine()
                .getCommandSpec().optionsMap().keySet().stream().filter(name -> name.startsWith("--"))
                .map(name -> name.substring(2)).toList()); // the names alone: the dashes are no part of a slip
        return nearest == null ? picocli
                : Stream.concat(Stream.of("--" + nearest), picocli.stream()).distinct().toList();
    }
}
