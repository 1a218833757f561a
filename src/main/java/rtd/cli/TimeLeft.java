package rtd.cli;

import java.util.OptionalDouble;

/**
 * A steady estimate of the time a phase has left, for the progress line.
 *
 * <p>The plain estimate, elapsed time × (work left / work done), swings when parts of a picture
 * differ in cost: empty rows go fast and rows full of objects slowly, so it jumped from 56 s to
 * 5 s. This one counts down between updates, and follows a new plain estimate only gradually
 * (exponential smoothing with a time constant of {@value #TIME_CONSTANT} s); it says nothing
 * until {@value #MIN_SECONDS} s or {@value #MIN_FRACTION} of the work have given it something to go on.
 */
final class TimeLeft {

    static final double TIME_CONSTANT = 3.0;
    static final double MIN_SECONDS = 1.5;
    static final double MIN_FRACTION = 0.05;

    private double estimate = Double.NaN;
    private double lastElapsed;

    /** The estimate after {@code elapsed} seconds with {@code fraction} (0 to 1) of the work done. */
    OptionalDouble update(double elapsed, double fraction) {
        if (!(fraction > 0) || elapsed < MIN_SECONDS && fraction < MIN_FRACTION) {
            return OptionalDouble.empty();
        }
        double plain = elapsed * (1 - Math.min(1, fraction)) / fraction;
        if (Double.isNaN(estimate)) {
            estimate = plain;
        } else {
            double step = Math.max(0, elapsed - lastElapsed);
            double countedDown = Math.max(0, estimate - step);
            double weight = 1 - Math.exp(-step / TIME_CONSTANT);
            estimate = countedDown + weight * (plain - countedDown);
        }
        lastElapsed = elapsed;
        return OptionalDouble.of(estimate);
    }
}
