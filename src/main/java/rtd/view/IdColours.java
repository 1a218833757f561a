package rtd.view;

/**
 * One colour per object for {@code --view id}: object i (from 0, in file order) gets
 * {@code (i + 1) · 0x9E3779 mod 2²⁴}. Multiplying by an odd number is a one-to-one map of the
 * 24-bit colours, so no two of the first 16,777,215 objects share a colour, and none is black,
 * the background; the golden-ratio factor puts neighbours in the file far apart in colour.
 */
public final class IdColours {

    private static final int FACTOR = 0x9E3779;

    private IdColours() {
    }

    /** The colour of object {@code index} as {@code 0xRRGGBB}; −1 (no object) is black. */
    public static int of(int index) {
        return index < 0 ? 0 : ((index + 1) * FACTOR) & 0xFFFFFF;
    }
}
