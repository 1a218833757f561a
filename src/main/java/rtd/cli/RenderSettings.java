package rtd.cli;

import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.Model.CommandSpec;

/**
 * The options of {@link RtdCommand} that the teaching options ({@link TeachingOptions}) need,
 * read from picocli's model of the command, so that those options live apart from the command's
 * own code.
 *
 * @param scenes  the scene files, as given
 * @param scene   the first of them, the one the teaching options work on
 * @param output  {@code -o}, or null
 * @param width   {@code --width}, times {@code --scale}
 * @param height  {@code --height}, times {@code --scale}
 * @param scale   {@code --scale}, for the camera
 * @param threads {@code --threads}
 * @param accel   {@code --accel}
 * @param samples {@code --samples}
 * @param paper   {@code --paper}: the paper's loop
 * @param stats   {@code --stats}: the time of each phase and the work per ray
 */
record RenderSettings(List<Path> scenes, Path scene, Path output, int width, int height, Scale scale, int threads,
        Accel accel, int samples, boolean paper, boolean stats) {

    /** The values the command line gave {@code command} (or their defaults), with {@code --scale} applied to the size. */
    static RenderSettings of(CommandSpec command) {
        List<Path> scenes = command.positionalParameters().get(0).getValue();
        Scale scale = command.findOption("--scale").getValue();
        int width = command.findOption("--width").getValue();
        int height = command.findOption("--height").getValue();
        return new RenderSettings(scenes, scenes.get(0), command.findOption("--output").getValue(),
                (int) Math.max(1, scale.times(width)), (int) Math.max(1, scale.times(height)), scale,
                command.findOption("--threads").getValue(), command.findOption("--accel").getValue(),
                command.findOption("--samples").getValue(), command.findOption("--paper").getValue(),
                command.findOption("--stats").getValue());
    }
}
