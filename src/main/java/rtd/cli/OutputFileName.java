package rtd.cli;

import java.io.File;
import java.nio.file.Path;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Reads the name of a file rtd writes ({@code -o}, {@code --export-pov}) as {@link FileName}
 * does, and refuses one that ends in a slash: {@code out/} names a folder, and Java would
 * quietly drop the slash and write a file called {@code out}, or replace one.
 */
final class OutputFileName implements ITypeConverter<Path> {

    @Override
    public Path convert(String value) {
        if (value.length() > 1 && (value.endsWith("/") || value.endsWith(File.separator))) {
            throw new TypeConversionException("'" + value + "' ends in '" + value.charAt(value.length() - 1)
                    + "', so it names a folder, not a file; add the file's name after it");
        }
        return new FileName().convert(value);
    }
}
