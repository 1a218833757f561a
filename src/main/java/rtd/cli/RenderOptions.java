package rtd.cli;

import java.nio.file.Path;
import java.util.List;

/**
 * What the command line asks of each run, sizes after {@code --scale}.
 *
 * @param scenes   the scene files as given; the teaching options work on the first
 * @param output   {@code -o}, or null
 * @param width    {@code --width} times {@code --scale}
 * @param height   {@code --height} times {@code --scale}
 * @param scale    {@code --scale}, for the camera
 * @param given    whether {@code --width} or {@code --height} was given, not left at its default
 * @param progress whether to show the progress line (on a terminal, without {@code --no-progress})
 * @param clock    {@code --clock}, the clock of a single picture (Part III); 0 by default
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
}
