package rtd.view;

/**
 * The colours of the views that colour by a number, as {@code 0xRRGGBB}.
 *
 * <ul>
 * <li>{@code --view cost}: black through purple, red and orange to pale yellow as a share from 0
 *     to 1 grows (a ramp like matplotlib's "inferno", readable in grey print too);</li>
 * <li>{@code --view id}: object i (from 0, in file order) gets {@code (i + 1) · 0x9E3779 mod 2²⁴}.
 *     Multiplying by an odd number is a one-to-one map of the 24-bit colours, so no two of the
 *     first 16,777,215 objects share a colour, and none is black, the background; the
 *     golden-ratio factor puts neighbours in the file far apart in colour.</li>
 * </ul>
 */
final class ViewColours {

    private static final int[][] HEAT_STOPS = {
        {0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};
    private static final int ID_FACTOR = 0x9E3779;

    private ViewColours() {
    }

    /** The cost view's colour of {@code share}, clamped to [0, 1]. */
    static int heat(double share) {
        double s = Math.max(0, Math.min(1, share)) * (HEAT_STOPS.length - 1);
        int low = Math.min((int) s, HEAT_STOPS.length - 2);
        double f = s - low;
        int rgb = 0;
        for (int k = 0; k < 3; k++) {
            int channel = (int) Math.round(HEAT_STOPS[low][k] + f * (HEAT_STOPS[low + 1][k] - HEAT_STOPS[low][k]));
            rgb = (rgb << 8) | channel;
        }
        return rgb;
    }

    /** The id view's colour of object {@code index}; −1 (no object) is black. */
    static int id(int index) {
        return index < 0 ? 0 : ((index + 1) * ID_FACTOR) & 0xFFFFFF;
    }
}
