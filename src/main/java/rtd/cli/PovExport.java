package rtd.cli;

import java.util.ArrayList;
import java.util.List;
import rtd.camera.ICamera;
import rtd.io.ClockedScene;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.pov.PovClock;
import rtd.pov.PovScene;
import rtd.scene.Scene;

/**
 * {@code --export-pov}: the scene's POV-Ray twin ({@link PovScene}), written all or nothing, and how to render it.
 * With {@code --frames N} (Part III, "Frames on the command line") one file holds the animation: each number that
 * uses the clock written with POV-Ray's {@code clock} ({@link PovClock}), or where one cannot be, each frame as a
 * still in a {@code #case} of {@code frame_number}; each of POV-Ray's frames is the twin of rtd's.
 */
final class PovExport {

    private PovExport() {
    }

    /** Writes {@code scene} to {@code target}; answers the lines saying how to render it. */
    static String still(Scene scene, OutputTarget target, int width, int height) throws SceneException, FileError {
        String name = target.spelt().getFileName().toString();
        write(target, () -> PovScene.of(scene, width, height, name));
        return "rtd: wrote " + target.spelt() + "; render it with POV-Ray (apt-get install povray):\n" + cd(target)
                + command(name, width, height);
    }

    /** Writes the animation's twin to {@code target}; answers the lines saying how to render it. */
    static String frames(SceneFile file, FramePlan plan, RenderOptions options, OutputTarget target)
            throws SceneException, FileError {
        String command = command(target.spelt().getFileName().toString(), options.width(), options.height())
                + " +KFI0 +KFF" + (plan.frames() - 1) + " +KI0 +KF1";
        String header = "// An animation of " + plan.frames() + " frames, written by rtd --export-pov --frames "
                + plan.frames() + ". Render all of them with\n//   " + command + "\n";
        write(target, () -> header + animation(file, plan, options));
        return "rtd: wrote " + target.spelt() + "; render its " + plan.frames() + " frames with POV-Ray:\n" + cd(target)
                + command;
    }

    /** Writes what {@code pov} makes; a scene POV-Ray cannot show is a file error. */
    private static void write(OutputTarget target, PovText pov) throws SceneException, FileError {
        String text;
        try {
            text = pov.text();
        } catch (IllegalArgumentException e) {
            throw new FileError("cannot export to POV-Ray: " + e.getMessage());
        }
        target.writeText(text); // outside the catch: a failed write is not a scene POV-Ray cannot show
    }

    private interface PovText {
        String text() throws SceneException;
    }

    private static String command(String name, int width, int height) {
        return PovScene.command(name, name.replaceAll("(?i)\\.pov$", "") + "-pov.png", width, height);
    }

    private static String cd(OutputTarget target) {
        return "  cd " + PovScene.shellWord(target.spelt().toAbsolutePath().getParent().toString()) + " && ";
    }

    /** The animation; a scene that uses the clock read at every frame's clock first: a mistake at one stops it. */
    private static String animation(SceneFile file, FramePlan plan, RenderOptions options) throws SceneException {
        List<ICamera> cameras = new ArrayList<>();
        for (int i = 0; file.usesClock() && i < plan.frames(); i++) {
            cameras.add(file.at(plan.clock(i), null).camera());
        }
        ClockedScene read = file.withClock(plan.clock(0));
        ClockedScene clocked = read.with(options.scale().of(read.scene()));
        if (!file.usesClock()) {
            return "// The scene does not use the clock: every frame is the same picture.\n"
                    + PovScene.of(clocked, options.width(), options.height());
        }
        boolean scaled = clocked.scene() != read.scene(); // the orthographic camera's zoom times --scale
        String why = scaled && !clocked.camera().isEmpty() ? "the orthographic camera at --scale"
                : PovClock.whyNot(clocked, cameras);
        if (why == null) {
            return "// Each number that uses rtd's clock is written with POV-Ray's clock, which runs from 0 to 1 over\n"
                    + "// the frames as rtd's does.\n" + PovScene.of(clocked, options.width(), options.height());
        }
        StringBuilder pov = new StringBuilder("// Each frame is rtd's scene at clock = frame_number/"
                + (plan.frames() - 1) + ", written out in the #case of its frame_number, since POV-Ray's clock\n"
                + "// cannot stand for the numbers that use rtd's clock in " + why + ".\n#version 3.7;\n\n"
                + "#switch (frame_number)\n");
        for (int i = 0; i < plan.frames(); i++) {
            Scene scene = options.scale().of(file.at(plan.clock(i), null));
            pov.append("#case (").append(i).append(")\n")
                    .append(PovScene.frame(scene, options.width(), options.height())).append("#break\n");
        }
        return pov.append("#end\n").toString();
    }
}
