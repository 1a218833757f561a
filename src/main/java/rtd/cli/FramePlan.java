package rtd.cli;

import java.nio.file.Path;
import java.util.Locale;

/**
 * Which frames of an animation a run draws and what each is called (Part III, "Frames on the command line"):
 * {@code --frames N} has frames 0 … N−1, frame i at {@code clock = i/(N−1)}, from 0 to 1 inclusive as
 * POV-Ray's clock runs; {@code --subset A-B} draws frames A to B of them, with the clocks and names they have
 * in the whole animation, so that machines can share the work. Numbered pictures are {@code NAME-000.png},
 * {@code NAME-001.png}, …: three digits, or as many as N−1 needs.
 *
 * @param frames the frames of the whole animation, at least 2
 * @param first  the first frame drawn
 * @param last   the last frame drawn, inclusive
 * @param fps    frames per second of an animated GIF
 */
record FramePlan(int frames, int first, int last, double fps) {

    /** The clock of frame {@code i} of the whole animation. */
    double clock(int i) {
        return i / (double) (frames - 1);
    }

    int count() {
        return last - first + 1;
    }

    /** The GIF's delay between frames, in hundredths of a second: round(100/F), at least 1. */
    int delayHundredths() {
        return (int) Math.max(1, Math.round(100 / fps));
    }

    /** The numbered picture of frame {@code i}: {@code out.png} gives {@code out-007.png}, {@code out} {@code out-007}. */
    Path frameFile(Path picture, int i) {
        String name = picture.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String number = String.format(Locale.ROOT, "-%0" + Math.max(3, String.valueOf(frames - 1).length()) + "d", i);
        String numbered = dot > 0 ? name.substring(0, dot) + number + name.substring(dot) : name + number;
        return picture.resolveSibling(numbered);
    }
}
