package rtd.cli;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Reads a file name from the command line, refusing one that Java cannot hold as it was typed.
 *
 * <p>Java decodes the command line with the system's encoding, which the locale sets
 * ({@code LC_ALL}, {@code LANG}). Bytes that do not decode become U+FFFD: under
 * {@code LC_ALL=C} every non-ASCII letter does, and under a UTF-8 locale every byte of a name
 * that is not UTF-8. Such a name would name a different file (one with U+FFFD in it) or none.
 */
final class FileName implements ITypeConverter<Path> {

    private static final char REPLACEMENT = '\uFFFD';

    @Override
    public Path convert(String value) {
        if (value.indexOf(REPLACEMENT) >= 0) {
            throw cannotUse(value);
        }
        try {
            return Path.of(value);
        } catch (InvalidPathException e) {
            throw cannotUse(value);
        }
    }

    private static TypeConversionException cannotUse(String value) {
        String encoding = System.getProperty("sun.jnu.encoding", System.getProperty("file.encoding", "?"));
        String shown = "the name '" + value.replace(REPLACEMENT, '?') + "' cannot be used: ";
        if (encoding.equalsIgnoreCase("UTF-8") || encoding.equalsIgnoreCase("UTF8")) {
            return new TypeConversionException(shown + "it is not valid UTF-8 (each '?' stands for bytes that are not); "
                    + "rename the file to a UTF-8 name");
        }
        return new TypeConversionException(shown + "it has characters that this system's encoding, " + encoding
                + ", cannot represent; run rtd under a UTF-8 locale, such as LC_ALL=C.UTF-8");
    }
}
