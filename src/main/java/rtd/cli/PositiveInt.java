package rtd.cli;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** Reads an option's value as a whole number greater than 0, such as {@code --width 800}. */
final class PositiveInt implements ITypeConverter<Integer> {

    @Override
    public Integer convert(String value) {
        try {
            int number = Integer.parseInt(value.trim());
            if (number > 0) {
                return number;
            }
        } catch (NumberFormatException e) {
            // answered below, with the same message as for 0 and negative numbers
        }
        throw new TypeConversionException("'" + value + "' is not a positive whole number");
    }
}
