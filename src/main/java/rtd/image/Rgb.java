package rtd.image;

/**
 * A colour with {@code float} channels, where 1 is full intensity: the colour that light carries
 * and that shading adds up (Part II, "Light"). The paper's 8-bit {@link Color} becomes one by
 * dividing by 255; {@link #toColor} turns it back, clamped and rounded.
 *
 * <p>Channels may leave [0, 1] while light is summed; only the final colour is clamped.
 */
public record Rgb(float red, float green, float blue) {

    /** No light. */
    public static final Rgb BLACK = new Rgb(0, 0, 0);

    /** The paper's colour {@code c} as channels from 0 to 1 ({@code c / 255}). */
    public static Rgb of(Color c) {
        return new Rgb(c.red() / 255f, c.green() / 255f, c.blue() / 255f);
    }

    /** The sum of two colours, channel by channel: light from two sources. */
    public Rgb plus(Rgb other) {
        return new Rgb(red + other.red, green + other.green, blue + other.blue);
    }

    /** This colour scaled by {@code factor}. */
    public Rgb times(float factor) {
        return new Rgb(red * factor, green * factor, blue * factor);
    }

    /** The product channel by channel ({@code ⊙}): a surface's colour lit by a light's colour. */
    public Rgb times(Rgb other) {
        return new Rgb(red * other.red, green * other.green, blue * other.blue);
    }

    /** Each channel clamped to [0, 1]: the most a pixel can show. */
    public Rgb clamped() {
        return new Rgb(clamp(red), clamp(green), clamp(blue));
    }

    /** The 8-bit colour: each channel clamped to [0, 1], then {@code floor(255·c + ½)}. */
    public Color toColor() {
        return new Color(toByte(red), toByte(green), toByte(blue));
    }

    private static float clamp(float channel) {
        return channel > 0 ? Math.min(1f, channel) : 0f; // NaN, too, becomes 0
    }

    private static int toByte(float channel) {
        return (int) Math.floor(255 * clamp(channel) + 0.5f);
    }
}
