package rtd.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.TypeConversionException;

/**
 * The options of motion, a picocli mixin of {@link RtdCommand} (Part III, "Frames on the command line"):
 * {@code --clock C} draws the scene at one clock, {@code --frames N} draws N frames from clock 0 to 1,
 * {@code --fps F} sets an animated GIF's speed and {@code --subset A-B} draws only some of the frames. Each
 * combination that cannot mean anything is refused as a mistake on the command line (exit code 2).
 */
public final class MotionOptions {

    /** The most frames an animation may have: a slip of a digit is caught, a long film is not refused. */
    static final int MOST_FRAMES = 1_000_000;

    @Option(names = "--clock", paramLabel = "C", converter = FiniteNumber.class,
            description = "the value of clock in the scene's expressions (default: 0)")
    private Double clock;

    @Option(names = "--frames", paramLabel = "N", converter = FrameCount.class,
            description = "draw N pictures (N at least 2), frame i at clock = i/(N-1): -o NAME.png writes NAME-000.png, "
                    + "NAME-001.png, ...; -o NAME.gif one looping animated GIF")
    private Integer frames;

    @Option(names = "--fps", paramLabel = "F", converter = FramesPerSecond.class,
            description = "frames per second of the animated GIF (default: 24)")
    private Double fps;

    @Option(names = "--subset", paramLabel = "A-B", description = "with --frames: draw only frames A to B (from 0, "
            + "inclusive), with the clocks and names they have in the whole animation")
    private String subset;

    /** The clock of a single picture: {@code --clock}, or 0. */
    double clock() {
        return clock == null ? 0 : clock;
    }

    /**
     * The frames to draw, or null for a single picture; every option that does not go with {@code --frames} (or
     * needs it) is refused, with {@code replacing} the teaching option that takes the picture's place, or null.
     */
    FramePlan plan(CommandLine commandLine, List<Path> scenes, Path output, String replacing) {
        if (frames == null) {
            for (String option : new String[] {subset != null ? "--subset" : null, fps != null ? "--fps" : null}) {
                if (option != null) {
                    throw misuse(commandLine, option + " belongs to an animation; give --frames N too");
                }
            }
            return null;
        }
        if (clock != null) {
            throw misuse(commandLine, "--frames gives each frame its own clock, from 0 to 1; --clock is for one picture");
        }
        if (replacing != null) {
            throw misuse(commandLine, replacing + " works on one picture, not on --frames; give --clock C for the moment "
                    + "you want");
        }
        if (scenes.size() > 1) {
            throw misuse(commandLine, "--frames works on one scene file, but " + scenes.size() + " were given; run rtd "
                    + "once for each");
        }
        if (OutputTarget.DASH.equals(output)) {
            throw misuse(commandLine, "--frames writes several pictures, which standard output (-o -) cannot hold; give "
                    + "a name such as -o frames.png (numbered frames) or -o movie.gif");
        }
        boolean gif = output != null && output.toString().toLowerCase(Locale.ROOT).endsWith(".gif");
        int[] range = range(commandLine);
        if (gif && subset != null) {
            throw misuse(commandLine, "--subset draws frames to be joined later, as numbered pictures; give -o NAME.png, "
                    + "and join the frames into a GIF or a video when all are drawn");
        }
        return new FramePlan(frames, range[0], range[1], fps == null ? 24 : fps);
    }

    private int[] range(CommandLine commandLine) {
        if (subset == null) {
            return new int[] {0, frames - 1};
        }
        Matcher matcher = Pattern.compile("\\s*(\\d{1,9})\\s*-\\s*(\\d{1,9})\\s*").matcher(subset);
        String frameRange = "from 0 to " + (frames - 1) + " (--frames " + frames + ")";
        if (!matcher.matches()) {
            throw misuse(commandLine, "--subset '" + subset + "': give the frames as A-B, two whole numbers " + frameRange
                    + ", such as --subset 0-" + (frames - 1) / 2);
        }
        int first = Integer.parseInt(matcher.group(1));
        int last = Integer.parseInt(matcher.group(2));
        if (first > last || last >= frames) {
            throw misuse(commandLine, "--subset " + first + "-" + last + ": " + (first > last ? "A must not be after B"
                    : "the frames run " + frameRange));
        }
        return new int[] {first, last};
    }

    private static ParameterException misuse(CommandLine commandLine, String message) {
        return new ParameterException(commandLine, message);
    }

    /** A finite number, for {@code --clock}. */
    static final class FiniteNumber implements ITypeConverter<Double> {
        @Override
        public Double convert(String value) {
            try {
                double number = Double.parseDouble(value.strip());
                if (Double.isFinite(number) && !value.strip().matches(".*[dDfFxX].*")) {
                    return number;
                }
            } catch (NumberFormatException e) {
                // said below
            }
            throw new TypeConversionException("'" + value + "' is not a number, such as 0.5");
        }
    }

    /** A whole number of frames, from 2 to {@link #MOST_FRAMES}. */
    static final class FrameCount implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            if (!value.strip().matches("\\d{1,9}") || Integer.parseInt(value.strip()) < 2
                    || Integer.parseInt(value.strip()) > MOST_FRAMES) {
                throw new TypeConversionException("'" + value + "' is not a whole number of frames from 2 to "
                        + String.format(Locale.ROOT, "%,d", MOST_FRAMES) + " (an animation has a first and a last frame)");
            }
            return Integer.parseInt(value.strip());
        }
    }

    /** Frames per second, above 0 and at most 100: a GIF counts its delays in hundredths of a second. */
    static final class FramesPerSecond implements ITypeConverter<Double> {
        @Override
        public Double convert(String value) {
            Double number = null;
            try {
                number = new FiniteNumber().convert(value);
            } catch (TypeConversionException e) {
                // said below
            }
            if (number == null || !(number > 0 && number <= 100)) {
                throw new TypeConversionException("'" + value + "' is not a number of frames per second above 0 and at "
                        + "most 100 (a GIF counts its frames' delays in hundredths of a second), such as 24");
            }
            return number;
        }
    }
}
