package rtd.cli;

import picocli.CommandLine.ITypeConverter;

/**
 * Reads {@code --threads N}: a whole number greater than 0, of which rtd uses at most
 * {@link #max()}. More threads than 4 per core only wait their turn, and cost: thousands made a
 * render of a second take twenty, and over 32,767 the JVM's fork/join pool (the BVH build) fails.
 */
final class ThreadCount implements ITypeConverter<Integer> {

    /** The most threads rtd uses: 4 per core that Java sees. */
    static int max() {
        return 4 * Runtime.getRuntime().availableProcessors();
    }

    @Override
    public Integer convert(String value) {
        return Math.min(new PositiveInt().convert(value), max());
    }
}
