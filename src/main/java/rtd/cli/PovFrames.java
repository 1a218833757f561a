package rtd.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.StandardOpenOption;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.pov.PovScene;

/**
 * {@code --export-pov} with {@code --frames N}: one POV-Ray file for the whole animation. Each frame is the scene
 * at its clock written as {@link PovScene} writes a still, in a {@code #case} of POV-Ray's {@code frame_number},
 * so that each of POV-Ray's frames is the exact twin of rtd's (the camera's half-pixel shift included); the file's
 * first lines give the {@code povray} options that render the same N frames, {@code +KFI0 +KFF(N−1)} with the
 * clock from 0 to 1. A scene that never uses the clock is written once.
 */
final class PovFrames {

    private PovFrames() {
    }

    /** Writes the animation's POV-Ray twin to {@code target}; answers the lines that say how to render it. */
    static String export(SceneFile file, FramePlan plan, RenderOptions options, OutputTarget target)
            throws SceneException, FileError {
        String name = target.spelt().getFileName().toString();
        String png = name.replaceAll("(?i)\\.pov$", "") + "-pov.png";
        String options4 = " +KFI0 +KFF" + (plan.frames() - 1) + " +KI0 +KF1";
        String command = PovScene.command(name, png, options.width(), options.height()) + options4;
        StringBuilder pov = new StringBuilder();
        pov.append("// An animation of ").append(plan.frames()).append(" frames, written by rtd --export-pov --frames ")
                .append(plan.frames()).append(". Render all of them with\n//   ").append(command).append('\n');
        pov.append("// Each frame is rtd's scene at clock = frame_number/").append(plan.frames() - 1)
                .append(", written out in the #case of its frame_number.\n");
        if (!file.usesClock()) {
            pov.append(still(file, 0, options, name));
        } else {
            pov.append("#switch (frame_number)\n");
            for (int i = 0; i < plan.frames(); i++) {
                pov.append("#case (").append(i).append(")\n").append(still(file, plan.clock(i), options, name))
                        .append("#break\n");
            }
            pov.append("#end\n");
        }
        try {
            if (target.kind() == OutputTarget.Kind.STREAM) {
                Files.writeString(target.file(), pov, StandardCharsets.UTF_8, StandardOpenOption.WRITE);
            } else {
                SceneRun.replaceWithText(target.file(), pov.toString());
            }
        } catch (IOException e) {
            throw new FileError("cannot write '" + target.spelt() + "'", e);
        }
        return "rtd: wrote " + target.spelt() + "; render its " + plan.frames() + " frames with POV-Ray:\n  cd "
                + PovScene.shellWord(target.spelt().toAbsolutePath().getParent().toString()) + " && " + command;
    }

    private static String still(SceneFile file, double clock, RenderOptions options, String name) throws SceneException,
            FileError {
        try {
            return PovScene.of(options.scale().of(file.at(clock, null)), options.width(), options.height(), name);
        } catch (IllegalArgumentException e) {
            throw new FileError("cannot export to POV-Ray: " + e.getMessage());
        }
    }
}
