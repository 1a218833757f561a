package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.OptionalDouble;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

@DisplayName("The progress line")
class ProgressDisplayTest {

    @ParameterizedTest(name = "{0} columns")
    @ValueSource(ints = {80, 41, 40, 30, 20, 12, 5, 1})
    void neverReachesTheLastColumnSoThatARedrawCannotWrapIntoANewLine(int columns) {
        String[] lines = {
            ProgressDisplay.Phase.fit("rendering", 0.42, "123.45 Mrays/s", OptionalDouble.of(3725), 12, columns),
            ProgressDisplay.Phase.fit("reading /home/student/scenes/a_very_long_name_of_a_scene_file.txt", Double.NaN, null,
                    OptionalDouble.empty(), 75, columns),
            ProgressDisplay.Phase.fit("writing out.png", 0.5, null, OptionalDouble.of(4), 2, columns)};
        for (String line : lines) {
            assertThat(line.length()).as(line).isLessThanOrEqualTo(Math.max(1, columns - 1));
            assertThat(line).doesNotContain("\n");
        }
    }

    @Test
    void showsPercentRateAndTimeLeftWhereThereIsRoom() {
        assertThat(ProgressDisplay.Phase.fit("rendering", 0.42, "3.21 Mrays/s", OptionalDouble.of(5.2), 3, 80))
                .isEqualTo("rendering   42%  3.21 Mrays/s  about 5 s left");
        assertThat(ProgressDisplay.Phase.fit("rendering", 0.42, "3.21 Mrays/s", OptionalDouble.of(5.2), 3, 30))
                .isEqualTo("rendering   42%  5 s left");
        assertThat(ProgressDisplay.Phase.fit("reading big.txt", Double.NaN, null, OptionalDouble.empty(), 3.4, 80))
                .isEqualTo("reading big.txt…  3 s");
    }

    @Test
    @DisplayName("The time left follows the rate of the last third of the time so far, so a render that speeds up as "
            + "the JIT compiles is not promised too long")
    void timeLeftFollowsTheRecentRate() {
        // a fake clock: an update every 0.25 s; 5 % of the rows a second for 2 s, then 20 % a second
        ProgressDisplay.Phase line = ProgressDisplay.Phase.of("rendering");
        OptionalDouble atThree = OptionalDouble.empty();
        OptionalDouble atFour = OptionalDouble.empty();
        for (int tick = 1; tick <= 16; tick++) {
            double t = tick * 0.25;
            double fraction = t <= 2 ? 0.05 * t : 0.10 + 0.20 * (t - 2);
            OptionalDouble left = line.timeLeft(t, fraction);
            atThree = tick == 12 ? left : atThree;
            atFour = tick == 16 ? left : atFour;
        }
        // at 3 s, 30 % done: the last second (a third of 3 s, at least 1 s), from 10 % to 30 %, went at 20 %/s, so
        // the 70 % left take 3.5 s (at the rate since the start, 10 %/s, 7 s)
        assertThat(atThree).hasValueCloseTo(3.5, within(1e-9));
        // at 4 s, 50 % done: the last update at least 4/3 s back is at 2.5 s, 20 %: 30 % in 1.5 s, 0.5 / 0.2 = 2.5 s
        assertThat(atFour).hasValueCloseTo(2.5, within(1e-9));
    }

    @Test
    @DisplayName("The rate is the rays traced, as --stats counts them, over the seconds of the render so far")
    void rateCountsRays() {
        // 2.5 s into the render, 40 % of the rows done, 19,525,000 rays traced (camera, shadow and mirror rays)
        assertThat(new ProgressDisplay.Phase("rendering", () -> 0.4, () -> 19_525_000).line(2.5, 80))
                .isEqualTo("rendering   40%  7.81 Mrays/s  about 4 s left");
    }

    @Test
    void saysNothingAboutTimeLeftBeforeItHasSomethingToGoOn() {
        assertThat(ProgressDisplay.Phase.of("rendering").timeLeft(1.0, 0.01)).isEmpty();
        assertThat(ProgressDisplay.Phase.of("rendering").timeLeft(0.5, 0.2)).isPresent();
        ProgressDisplay.Phase stalled = ProgressDisplay.Phase.of("rendering");
        stalled.timeLeft(2, 0.3);
        assertThat(stalled.timeLeft(3.5, 0.3)).as("no rows done in the last second").isEmpty();
    }

    @Test
    void isClearedByTheShutdownHookThatCtrlCRuns() {
        StringWriter err = new StringWriter();
        ProgressDisplay display = new ProgressDisplay(new PrintWriter(err, true), () -> 40);
        display.show(ProgressDisplay.Phase.counted("rendering", () -> 0.5));
        display.draw();
        assertThat(err.toString()).startsWith("\rrendering").doesNotContain("\n");
        display.clearOnExit.run(); // what the JVM runs on SIGINT
        assertThat(err.toString()).endsWith("\r\033[K");
        display.close();
    }

    @Test
    void movesOutOfTheWayOfAWarning() {
        StringWriter err = new StringWriter();
        ProgressDisplay display = new ProgressDisplay(new PrintWriter(err, true), () -> 80);
        display.show(ProgressDisplay.Phase.of("reading scene.txt"));
        display.draw();
        display.message("rtd: warning: ...");
        assertThat(err.toString()).endsWith("\r\033[Krtd: warning: ...\n");
        display.close();
        assertThat(err.toString()).endsWith("\r\033[K");
    }
}
