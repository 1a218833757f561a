package rtd.view;

/**
 * The colours of {@code --view cost}: black through purple, red and orange to pale yellow as a
 * share from 0 to 1 grows (a ramp like matplotlib's "inferno", readable in grey print too).
 */
final class HeatMap {

    private static final int[][] STOPS = {
        {0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};

    private HeatMap() {
    }

    /** The colour of {@code share} (clamped to [0, 1]) as {@code 0xRRGGBB}. */
    static int of(double share) {
        double s = Math.max(0, Math.min(1, share)) * (STOPS.length - 1);
        int low = Math.min((int) s, STOPS.length - 2);
        double f = s - low;
        int rgb = 0;
        for (int k = 0; k < 3; k++) {
            int channel = (int) Math.round(STOPS[low][k] + f * (STOPS[low + 1][k] - STOPS[low][k]));
            rgb = (rgb << 8) | channel;
        }
        return rgb;
    }
}
