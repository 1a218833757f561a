package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/**
 * A full disk and a read-only folder, made with a small tmpfs (the tests run as root, who may
 * write any folder of a writable file system): the old picture stays, and no temporary file.
 */
@DisplayName("Folders that cannot take the picture")
class UnwritableFolderTest {

    private static final String EXAMPLE = Path.of("examples", "input_rtd.txt").toString();

    @TempDir
    Path dir;
    private Path mounted;

    private static boolean run(String... command) throws IOException, InterruptedException {
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        return process.waitFor(20, TimeUnit.SECONDS) && process.exitValue() == 0;
    }

    /** A tmpfs of {@code size} at dir/mnt holding out.png = {1, 2, 3}, remounted with {@code options}. */
    private Path folder(String size, String options) throws Exception {
        Path mount = Files.createDirectory(dir.resolve("mnt"));
        assumeThat(run("mount", "-t", "tmpfs", "-o", "size=" + size, "tmpfs", mount.toString())).as("mount works (root)").isTrue();
        mounted = mount;
        Files.write(mount.resolve("out.png"), new byte[] {1, 2, 3});
        assertThat(run("mount", "-o", "remount," + options, mount.toString())).isTrue();
        return mount;
    }

    @AfterEach
    void unmount() throws Exception {
        if (mounted != null) {
            run("umount", mounted.toString());
        }
    }

    private static String[] namesIn(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).toArray(String[]::new);
        }
    }

    @Test
    void aFullDiskFailsTheWriteAndLeavesTheOldFileAndNoTemporaryFile() throws Exception {
        Path folder = folder("12k", "rw");
        Run run = Cli.run(EXAMPLE, "-o", folder.resolve("out.png").toString(), "--width", "1920", "--height", "1080");
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).isEqualTo("rtd: cannot write '" + folder.resolve("out.png") + "': no space left on device\n");
        assertThat(namesIn(folder)).containsExactly("out.png");
        assertThat(Files.readAllBytes(folder.resolve("out.png"))).containsExactly(1, 2, 3);
    }

    @Test
    void aReadOnlyFolderIsRefusedBeforeRenderingAndTheOldFileStays() throws Exception {
        Path folder = folder("1m", "ro");
        Run run = Cli.run(EXAMPLE, "-o", folder.resolve("out.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).isEqualTo("rtd: cannot write '" + folder.resolve("out.png") + "': the folder '" + folder
                + "' is not writable\n");
        assertThat(namesIn(folder)).containsExactly("out.png");
        assertThat(Files.readAllBytes(folder.resolve("out.png"))).containsExactly(1, 2, 3);
    }
}
