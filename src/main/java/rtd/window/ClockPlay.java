package rtd.window;

/**
 * The play key's clock: it runs from where it is towards 1 and wraps round to 0, one pass from 0 to 1 in
 * {@link #PASS_NANOS}, as the frames of an animation loop. Time, not frames, moves it, so a slow scene plays at the
 * same pace in fewer frames.
 */
final class ClockPlay {

    /** One pass of the clock from 0 to 1: 5 seconds. */
    static final long PASS_NANOS = 5_000_000_000L;
    /** How often the window asks for the next frame while playing: 25 times a second at most. */
    static final int TICK_MILLIS = 40;

    private ClockPlay() {
    }

    /** The clock {@code elapsedNanos} after {@code clock}, wrapped into [0, 1). */
    static double next(double clock, long elapsedNanos) {
        double next = clock + (double) elapsedNanos / PASS_NANOS;
        return next - Math.floor(next);
    }
}
