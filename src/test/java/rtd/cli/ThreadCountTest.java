package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

@DisplayName("--threads")
class ThreadCountTest {

    @TempDir
    Path dir;

    @Test
    void aCountAboveWhatTheForkJoinPoolTakesRendersALargeSceneWithAtMostFourThreadsPerCore() throws IOException {
        // Large enough that the BVH is built in parallel (20,000 objects or more).
        StringBuilder scene = new StringBuilder("orthographic_camera:(0|0|100):(0|0|-1):(100)\n");
        Random random = new Random(13);
        for (int i = 0; i < 25_000; i++) {
            scene.append(String.format(Locale.ROOT, "sphere:(%.2f|%.2f|%.2f):(0.3):(200|10|10)%n",
                    random.nextFloat() * 100 - 50, random.nextFloat() * 100 - 50, random.nextFloat() * 100 - 50));
        }
        Path file = Files.writeString(dir.resolve("many.txt"), scene);
        Run run = Cli.run(file.toString(), "-o", dir.resolve("out.png").toString(), "--threads", "40000", "--stats",
                "--width", "64", "--height", "36");
        assertThat(run.exitCode()).as(run.err()).isZero();
        int max = 4 * Runtime.getRuntime().availableProcessors();
        assertThat(run.err()).contains("rays on " + max + " threads");
    }

    @Test
    void helpSaysThatAtMostFourThreadsPerCoreAreUsed() {
        assertThat(Cli.run("--help").out().replaceAll("\\s+", " ")).contains("at most 4 threads per core");
    }
}
