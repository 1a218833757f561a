package rtd.cli;

import java.nio.file.Path;
import java.util.List;

/** A mistake on the command line found while planning the run, reported as picocli reports one (exit code 2). */
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
}
