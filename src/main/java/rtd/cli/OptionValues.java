package rtd.cli;

import java.io.File;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** How {@link RtdCommand} reads its options' values: each converter gives the value, or says what is wrong with it. */
final class OptionValues {

    private OptionValues() {
    }

    /** A whole number greater than 0, such as {@code --width 800}. */
    static final class PositiveWhole implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            try {
                int number = Integer.parseInt(value.trim());
                if (number > 0) {
                    return number;
                }
            } catch (NumberFormatException e) {
                // answered below, as 0 and negative numbers are
            }
            throw new TypeConversionException("'" + value + "' is not a positive whole number");
        }
    }

    /**
     * {@code --threads N}, of which rtd uses at most {@link #max()}: more only wait their turn and cost, and over
     * 32,767 the JVM's fork/join pool (the BVH build) fails.
     */
    static final class Threads implements ITypeConverter<Integer> {
        static int max() {
            return 4 * Runtime.getRuntime().availableProcessors();
        }

        @Override
        public Integer convert(String value) {
            return Math.min(new PositiveWhole().convert(value), max());
        }
    }

    /** {@code --samples N}, 1 to {@value #MOST}: N × N rays a pixel, so that a slip such as 1000 cannot run for hours. */
    static final class Samples implements ITypeConverter<Integer> {
        static final int MOST = 16;

        @Override
        public Integer convert(String value) {
            int samples = new PositiveWhole().convert(value);
            if (samples > MOST) {
                throw new TypeConversionException("'" + value + "' is more than " + MOST + ": --samples N traces N × N "
                        + "rays through each pixel, so " + MOST + " is " + MOST * MOST + " rays a pixel already; 2 to 4 "
                        + "smooth the edges well");
            }
            return samples;
        }
    }

    /** {@code --scale F}: a decimal number greater than 0 (digits and a point only: no NaN, hexadecimal or "2d"). */
    static final class ScaleFactor implements ITypeConverter<Scale> {
        @Override
        public Scale convert(String value) {
            String text = value.trim();
            if (text.matches("[0-9]*\\.?[0-9]+([eE][-+]?[0-9]+)?|[0-9]+\\.")) {
                double factor = Double.parseDouble(text);
                if (factor > 0 && Double.isFinite(factor)) {
                    return new Scale(factor);
                }
            }
            throw new TypeConversionException("'" + value + "' is not a number greater than 0, such as 0.25 or 2");
        }
    }

    /**
     * A file name that Java holds as it was typed. Java decodes the command line in the locale's encoding, and
     * bytes that do not decode become U+FFFD: such a name would name another file, or none.
     */
    static final class FileName implements ITypeConverter<Path> {
        private static final char REPLACEMENT = '\uFFFD';

        @Override
        public Path convert(String value) {
            try {
                if (value.indexOf(REPLACEMENT) < 0) {
                    return Path.of(value);
                }
            } catch (InvalidPathException e) {
                // answered below
            }
            String encoding = System.getProperty("sun.jnu.encoding", System.getProperty("file.encoding", "?"));
            String shown = "the name '" + value.replace(REPLACEMENT, '?') + "' cannot be used: ";
            if (encoding.equalsIgnoreCase("UTF-8") || encoding.equalsIgnoreCase("UTF8")) {
                throw new TypeConversionException(shown + "it is not valid UTF-8 (each '?' stands for bytes that are "
                        + "not); rename the file to a UTF-8 name");
            }
            throw new TypeConversionException(shown + "it has characters that this system's encoding, " + encoding
                    + ", cannot represent; run rtd under a UTF-8 locale, such as LC_ALL=C.UTF-8");
        }
    }

    /** A file rtd writes ({@code -o}, {@code --export-pov}): never a name ending in a slash, which Java would drop. */
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
}
