package rtd.cli;

import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.Model.CommandSpec;

/**
 * The options of {@link RtdCommand} that the teaching options ({@link TeachingOptions}) need,
 * read from picocli's model of the command, so that those options live apart from the command's
 * own code.
 *
 * @param scene   the scene file
 * @param output  {@code -o}, or null
 * @param width   {@code --width}
 * @param height  {@code --height}
 * @param threads {@code --threads}
 * @param accel   {@code --accel}
 * @param samples {@code --samples}
 * @param paper   {@code --paper}: the paper's loop
 */
record RenderSettings(Path scene, Path output, int width, int height, int threads, Accel accel, int samples,
        boolean paper) {

    /** The values the command line gave {@code command} (or their defaults). */
    static RenderSettings of(CommandSpec command) {
        List<Path> scenes = command.positionalParameters().get(0).getValue();
        return new RenderSettings(scenes.get(0),
                command.findOption("--output").getValue(), command.findOption("--width").getValue(),
                command.findOption("--height").getValue(), command.findOption("--threads").getValue(),
                command.findOption("--accel").getValue(), command.findOption("--samples").getValue(),
                command.findOption("--paper").getValue());
    }

    /** Whether to trace with the BVH: as {@code rtd} renders, {@code auto} takes it for any scene with objects. */
    boolean useBvh(int objects) {
        return !paper && accel.usesBvh(objects);
    }
}
