package rtd.cli;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Reads {@code --samples N}: a whole number from 1 to {@value #MOST}. N × N rays go through each
 * pixel, so the work grows with N²; a slip such as {@code --samples 1000} would trace a million
 * rays a pixel for hours, without a word.
 */
final class SampleCount implements ITypeConverter<Integer> {

    /** 256 rays a pixel: far more than it takes to smooth an edge (4 gives 16 shades along it). */
    static final int MOST = 16;

    @Override
    public Integer convert(String value) {
        int samples = new PositiveInt().convert(value);
        if (samples > MOST) {
            throw new TypeConversionException("'" + value + "' is more than " + MOST + ": --samples N traces N × N rays "
                    + "through each pixel, so " + MOST + " is " + MOST * MOST + " rays a pixel already; 2 to 4 smooth the "
                    + "edges well");
        }
        return samples;
    }
}
