package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
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
            ProgressText.line("rendering", 0.42, "123.45 Mrays/s", OptionalDouble.of(3725), 12, columns),
            ProgressText.line("reading /home/student/scenes/a_very_long_name_of_a_scene_file.txt", Double.NaN, null,
                    OptionalDouble.empty(), 75, columns),
            ProgressText.line("writing out.png", 0.5, null, OptionalDouble.of(4), 2, columns)};
        for (String line : lines) {
            assertThat(line.length()).as(line).isLessThanOrEqualTo(Math.max(1, columns - 1));
            assertThat(line).doesNotContain("\n");
        }
    }

    @Test
    void showsPercentRateAndTimeLeftWhereThereIsRoom() {
        assertThat(ProgressText.line("rendering", 0.42, "3.21 Mrays/s", OptionalDouble.of(5.2), 3, 80))
                .isEqualTo("rendering   42%  3.21 Mrays/s  about 5 s left");
        assertThat(ProgressText.line("rendering", 0.42, "3.21 Mrays/s", OptionalDouble.of(5.2), 3, 30))
                .isEqualTo("rendering   42%  5 s left");
        assertThat(ProgressText.line("reading big.txt", Double.NaN, null, OptionalDouble.empty(), 3.4, 80))
                .isEqualTo("reading big.txt…  3 s");
    }

    @Test
    void theTimeLeftDoesNotSwingWhenThePaceChanges() {
        TimeLeft timeLeft = new TimeLeft();
        // 2 s for the first 3.4 % (56 s left at that pace), then the work goes five times as fast
        List<Double> shown = new ArrayList<>();
        double fraction = 0;
        for (double t = 0.25; t <= 2; t += 0.25) {
            fraction = 0.017 * t;
            timeLeft.update(t, fraction).ifPresent(shown::add);
        }
        for (double t = 2.25; t <= 8; t += 0.25) {
            fraction += 0.017 * 0.25 * 5;
            timeLeft.update(t, fraction).ifPresent(shown::add);
        }
        assertThat(shown.get(0)).isGreaterThan(50);
        for (int i = 1; i < shown.size(); i++) {
            // never more than a tenth of the way from one redraw (a quarter of a second) to the next, plus the count-down
            assertThat(shown.get(i)).as("step %d", i).isGreaterThan(shown.get(i - 1) * 0.9 - 0.25 - 1e-9);
        }
        assertThat(shown.get(shown.size() - 1)).as("follows the new pace").isLessThan(shown.get(0) / 3);
    }

    @Test
    void saysNothingAboutTimeLeftBeforeItHasSomethingToGoOn() {
        assertThat(new TimeLeft().update(1.0, 0.01)).isEmpty();
        assertThat(new TimeLeft().update(0.5, 0.2)).isPresent();
    }

    @Test
    void isClearedByTheShutdownHookThatCtrlCRuns() {
        StringWriter err = new StringWriter();
        ProgressDisplay display = new ProgressDisplay(new PrintWriter(err, true), () -> 40, 0);
        display.show(ProgressDisplay.Phase.counted("rendering", () -> 0.5));
        display.draw();
        assertThat(err.toString()).startsWith("\rrendering").doesNotContain("\n");
        display.shutdownHook().run(); // what the JVM runs on SIGINT
        assertThat(err.toString()).endsWith("\r\033[K");
        display.close();
    }

    @Test
    void movesOutOfTheWayOfAWarning() {
        StringWriter err = new StringWriter();
        ProgressDisplay display = new ProgressDisplay(new PrintWriter(err, true), () -> 80, 0);
        display.show(ProgressDisplay.Phase.of("reading scene.txt"));
        display.draw();
        display.message("rtd: warning: ...");
        assertThat(err.toString()).endsWith("\r\033[Krtd: warning: ...\n");
        display.close();
        assertThat(err.toString()).endsWith("\r\033[K");
    }
}
