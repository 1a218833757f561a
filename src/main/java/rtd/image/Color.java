package rtd.image;

/**
 * The paper's colour: RGB, 8 bits a channel, as the scene file writes it and the PNG stores it
 * (section 4.1).
 */
public record Color(int red, int green, int blue) {

    /** Black, the background of a scene that names no {@code ambient} colour. */
    public static final Color BLACK = new Color(0, 0, 0);

    /** Checks that each channel lies in 0–255. */
    public Color {
        checkChannel("red", red);
        checkChannel("green", green);
        checkChannel("blue", blue);
    }

    private static void checkChannel(String name, int value) {
        if (value < 0 || value > 255) {
            throw new IllegalArgumentException(name + " must be in 0-255, found " + value);
        }
    }

    /** Returns the colour packed as {@code 0xRRGGBB}, the layout of {@code BufferedImage.setRGB}. */
    public int getRGB() {
        return (red << 16) | (green << 8) | blue;
    }

    /** Returns the colour whose packed form is {@code rgb}; the top 8 bits are ignored. */
    public static Color fromRGB(int rgb) {
        return new Color((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF);
    }

    @Override
    public String toString() {
        return "(" + red + "|" + green + "|" + blue + ")";
    }
}
