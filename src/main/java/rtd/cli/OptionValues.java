package rtd.cli;

import java.io.File;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** How {@link RtdCommand} reads its options' values: each converter gives the value, or says what is wrong with it. */
final class OptionValues {

    /** The most frames an animation may have: a slip of a digit is caught, a long film is not refused. */
    static final int MOST_FRAMES = 1_000_000;

    private OptionValues() {
    }

    private static <T> T orRefuse(T value, String message) {
        if (value == null) {
            throw new TypeConversionException(message);
        }
        return value;
    }

    /** {@code value} as a finite decimal number (no hexadecimal, no "2d" or "2f"), or NaN. */
    private static double finite(String value) {
        try {
            double number = Double.parseDouble(value.strip());
            return Double.isFinite(number) && !value.strip().matches(".*[dDfFxX].*") ? number : Double.NaN;
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /** A whole number greater than 0, such as {@code --width 800}. */
    static final class PositiveWhole implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            int number;
            try {
                number = Integer.parseInt(value.trim());
            } catch (NumberFormatException e) {
                number = 0; // refused as 0 and negative numbers are
            }
            return orRefuse(number > 0 ? number : null, "'" + value + "' is not a positive whole number");
        }
    }

    /** {@code --threads N}, at most 4 a core: more only wait their turn, and over 32,767 fork/join fails. */
    static final class Threads implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            return Math.min(new PositiveWhole().convert(value), 4 * Runtime.getRuntime().availableProcessors());
        }
    }

    /** {@code --samples N}, 1 to {@value #MOST}: N × N rays a pixel, so that a slip cannot run for hours. */
    static final class Samples implements ITypeConverter<Integer> {
        static final int MOST = 16;

        @Override
        public Integer convert(String value) {
            int samples = new PositiveWhole().convert(value);
            return orRefuse(samples <= MOST ? samples : null, "'" + value + "' is more than " + MOST + ": --samples N "
                    + "traces N × N rays through each pixel, so " + MOST + " is " + MOST * MOST + " rays a pixel "
                    + "already; 2 to 4 smooth the edges well");
        }
    }

    /** {@code --scale F}: a decimal number greater than 0 (digits and a point only: no NaN, hexadecimal or "2d"). */
    static final class ScaleFactor implements ITypeConverter<Scale> {
        @Override
        public Scale convert(String value) {
            String text = value.trim();
            double factor = text.matches("[0-9]*\\.?[0-9]+([eE][-+]?[0-9]+)?|[0-9]+\\.") ? Double.parseDouble(text) : 0;
            return orRefuse(factor > 0 && Double.isFinite(factor) ? new Scale(factor) : null, "'" + value
                    + "' is not a number greater than 0, such as 0.25 or 2");
        }
    }

    /**
     * A file name that Java holds as it was typed. Java decodes the command line in the locale's encoding, and
     * bytes that do not decode become U+FFFD: such a name would name another file, or none.
     */
    static final class FileName implements ITypeConverter<Path> {
        @Override
        public Path convert(String value) {
            try {
                if (value.indexOf('\uFFFD') < 0) {
                    return Path.of(value);
                }
            } catch (InvalidPathException e) {
                // answered below
            }
            String encoding = System.getProperty("sun.jnu.encoding", System.getProperty("file.encoding", "?"));
            String shown = "the name '" + value.replace('\uFFFD', '?') + "' cannot be used: ";
            throw new TypeConversionException(shown + (encoding.equalsIgnoreCase("UTF-8") || encoding.equalsIgnoreCase(
                    "UTF8") ? "it is not valid UTF-8 (each '?' stands for bytes that are not); rename the file to a "
                    + "UTF-8 name" : "it has characters that this system's encoding, " + encoding + ", cannot "
                    + "represent; run rtd under a UTF-8 locale, such as LC_ALL=C.UTF-8"));
        }
    }

    /** A file rtd writes: never a name ending in a slash, which Java would drop. */
    static final class OutputFile implements ITypeConverter<Path> {
        @Override
        public Path convert(String value) {
            if (value.length() > 1 && (value.endsWith("/") || value.endsWith(File.separator))) {
                throw new TypeConversionException("'" + value + "' ends in '" + value.charAt(value.length() - 1)
                        + "', so it names a folder, not a file; add the file's name after it");
            }
            return new FileName().convert(value);
        }
    }

    /** A finite number, for {@code --clock}. */
    static final class FiniteNumber implements ITypeConverter<Double> {
        @Override
        public Double convert(String value) {
            double number = finite(value);
            return orRefuse(Double.isNaN(number) ? null : number, "'" + value + "' is not a number, such as 0.5");
        }
    }

    /** {@code --frames N}: a whole number of frames, from 2 to {@link #MOST_FRAMES}. */
    static final class FrameCount implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            int frames = value.strip().matches("[0-9]{1,9}") ? Integer.parseInt(value.strip()) : 0;
            return orRefuse(frames >= 2 && frames <= MOST_FRAMES ? frames : null, String.format(Locale.ROOT, "'%s' is "
                    + "not a whole number of frames from 2 to %,d (an animation has a first and a last frame)", value,
                    MOST_FRAMES));
        }
    }

    /** {@code --fps F}: above 0 and at most 100, as a GIF counts its delays in hundredths of a second. */
    static final class FramesPerSecond implements ITypeConverter<Double> {
        @Override
        public Double convert(String value) {
            double number = finite(value);
            return orRefuse(number > 0 && number <= 100 ? number : null, "'" + value + "' is not a number of frames "
                    + "per second above 0 and at most 100 (a GIF counts its frames' delays in hundredths of a second), "
                    + "such as 24");
        }
    }
}
