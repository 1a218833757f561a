package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** Scene files that are no scene: the message names the file and says why, with exit code 1. */
@DisplayName("Scene files that are endless or huge")
class SceneInputTest {

    @TempDir
    Path dir;

    @Test
    void aThreeGibFileIsRefusedWithItsNameAndSizeNotWithAdviceAboutMemory() throws IOException {
        Path huge = dir.resolve("huge.txt");
        try (RandomAccessFile file = new RandomAccessFile(huge.toFile(), "rw")) {
            file.setLength(3L << 30); // sparse: no disk, no time
        }
        Run run = Cli.run(huge.toString(), "-o", dir.resolve("out.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).startsWith("rtd: cannot read the scene file '" + huge + "': it is 3.0 GiB; "
                + "rtd reads scene files of at most 1.0 GiB").doesNotContain("memory");
    }

    @Test
    void devZeroIsNotATextFileAndEndsAtOnce() {
        Run run = Cli.run("/dev/zero", "-o", dir.resolve("out.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).startsWith("/dev/zero:1:1: error: this is not a text file: found a NUL byte\n")
                .doesNotContain("memory");
    }
}
