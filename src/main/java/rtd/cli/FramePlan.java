package rtd.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import rtd.io.SceneError;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.scene.Scene;
import rtd.scene.SceneWarnings;

/**
 * Which frames of an animation a run draws (Part III, "Frames on the command line"), {@code first} to {@code last}
 * of frames 0 … N−1, frame i at {@code clock = i/(N−1)} as POV-Ray's clock runs, and what each is called:
 * {@code NAME-000.png}, … .
 */
record FramePlan(int frames, int first, int last, double fps) {

    double clock(int i) {
        return i / (double) (frames - 1);
    }

    int count() {
        return last - first + 1;
    }

    /** The GIF's delay between frames in hundredths of a second, at least 1. */
    int delayHundredths() {
        return (int) Math.max(1, Math.round(100 / fps));
    }

    /** The picture of frame {@code i}: {@code out.png} gives {@code out-007.png}, {@code out} {@code out-007}. */
    Path frameFile(Path picture, int i) {
        String name = picture.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String number = String.format(Locale.ROOT, "-%0" + Math.max(3, String.valueOf(frames - 1).length()) + "d", i);
        return picture.resolveSibling(dot > 0 ? name.substring(0, dot) + number + name.substring(dot) : name + number);
    }

    /** Each numbered picture's target beside {@code target}, all checked before anything is drawn. */
    List<OutputTarget> targets(OutputTarget target, Path scene) throws FileError {
        if (target.kind() == OutputTarget.Kind.STREAM) {
            return Collections.nCopies(count(), target);
        }
        List<OutputTarget> targets = new ArrayList<>();
        for (int i = first; i <= last; i++) {
            targets.add(OutputTarget.of(frameFile(target.spelt(), i), scene, "-o"));
        }
        return targets;
    }

    /** The scene at frame {@code i}'s clock, {@code scale}d; a mistake names the clock if its message does not. */
    Scene frame(SceneFile file, Scale scale, int i, List<SceneError> warnings) throws SceneException {
        try {
            return scale.of(file.at(clock(i), warnings));
        } catch (SceneException e) {
            throw new SceneException(e.errors().stream().map(error -> error.message().contains("clock =") ? error
                    : new SceneError(error.file(), error.line(), error.column(), error.message() + " (frame " + i
                            + ", at clock = " + SceneWarnings.number(clock(i)) + ")", error.sourceLine(),
                            error.help()))
                    .toList(), false);
        }
    }

    /**
     * The frames that {@code --frames}, {@code --subset} and {@code --fps} ask for (each null if not given), or null
     * for one picture; a misuse for what does not go with {@code --frames}: {@code --clock} if {@code clockGiven}, the
     * option {@code replacing} the picture, several scenes or standard output.
     */
    static FramePlan of(Integer frames, String subset, Double fps, boolean clockGiven, List<Path> scenes, Path output,
            String replacing) {
        if (frames == null) {
            Misuse.refuse(subset != null || fps != null, (subset != null ? "--subset" : "--fps")
                    + " belongs to an animation; give --frames N too");
            return null;
        }
        Misuse.refuse(clockGiven, "--frames gives each frame its own clock, from 0 to 1; --clock "
                + "is for one picture");
        Misuse.refuse(replacing != null, replacing + " works on one picture, not on --frames; give "
                + "--clock C for the moment you want");
        Misuse.oneSceneFile("--frames", scenes);
        Misuse.refuse(OutputTarget.DASH.equals(output), "--frames writes several pictures, which standard output "
                + "(-o -) cannot hold; give a name such as -o frames.png (numbered frames) or -o movie.gif");
        double speed = fps == null ? 24 : fps;
        if (subset == null) {
            return new FramePlan(frames, 0, frames - 1, speed);
        }
        Matcher matcher = Pattern.compile("\\s*(\\d{1,9})\\s*-\\s*(\\d{1,9})\\s*").matcher(subset);
        String frameRange = "from 0 to " + (frames - 1) + " (--frames " + frames + ")";
        Misuse.refuse(!matcher.matches(), "--subset '" + subset + "': give the frames as A-B, two "
                + "whole numbers " + frameRange + ", such as --subset 0-" + (frames - 1) / 2);
        int first = Integer.parseInt(matcher.group(1));
        int last = Integer.parseInt(matcher.group(2));
        Misuse.refuse(first > last || last >= frames, "--subset " + first + "-" + last + ": "
                + (first > last ? "A must not be after B" : "the frames run " + frameRange));
        Misuse.refuse(output != null && output.toString().toLowerCase(Locale.ROOT).endsWith(".gif"),
                "--subset draws frames to be joined later, as numbered pictures; give -o NAME.png, and join the frames "
                + "into a GIF or a video when all are drawn");
        return new FramePlan(frames, first, last, speed);
    }
}
