package rtd.cli;

import java.nio.file.Path;
import java.util.List;
import rtd.accel.Accelerator;

/**
 * What the command line asks of each run: {@code width} and {@code height} after {@code --scale}; {@code given}
 * whether {@code --width} or {@code --height} was; {@code progress} whether to show the progress line; {@code clock}
 * that of a single picture (Part III).
 */
record RenderOptions(List<Path> scenes, Path output, int width, int height, Scale scale, boolean given, int threads,
        Accelerator.Choice accel, boolean paper, int samples, boolean stats, boolean progress, double clock) {

    Path scene() {
        return scenes.get(0);
    }

    /** What finds the hits: {@code --accel}, or for {@code --paper} the paper's loop. */
    Accelerator.Choice engine() {
        return paper ? Accelerator.Choice.none : accel;
    }

    /** The threads that parse the scene: for {@code --paper} one, which reads the file line by line, as the paper. */
    int parseThreads() {
        return paper ? 1 : threads;
    }
}
