package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.io.IOException;
import java.io.InputStream;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** Links, FIFOs, devices and sockets as the output: nothing but a regular file is ever replaced. */
@DisplayName("The output, when it is not a plain new file")
class OutputTargetTest {

    private static final Path EXAMPLE = Path.of("examples", "input_rtd.txt");
    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

    @TempDir
    Path dir;

    private Path scene() throws IOException {
        return Files.copy(EXAMPLE, dir.resolve("scene.txt"));
    }

    private static Run render(Path scene, Path output) {
        return Cli.run(scene.toString(), "-o", output.toString(), "--width", "32", "--height", "18");
    }

    private static boolean isOther(Path path) throws IOException {
        return Files.readAttributes(path, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS).isOther();
    }

    @Test
    void anOutputThatIsALinkToTheSceneIsRefusedAndTheSceneIsKept() throws IOException {
        Path scene = scene();
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), scene.getFileName());
        Run run = render(scene, link);
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).startsWith("rtd: the output '" + link + "' is the scene file itself; choose another with -o");
        assertThat(Files.readString(scene)).isEqualTo(Files.readString(EXAMPLE));
        assertThat(link).isSymbolicLink();
    }

    @Test
    void anOutputThatReachesTheSceneThroughALinkedFolderIsRefusedAndTheSceneIsKept() throws IOException {
        Path scene = scene();
        Path linkedFolder = Files.createSymbolicLink(dir.resolve("same"), dir);
        Run run = render(scene, linkedFolder.resolve("scene.txt"));
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("is the scene file itself");
        assertThat(Files.readString(scene)).isEqualTo(Files.readString(EXAMPLE));
    }

    @Test
    void anOutputThatIsALinkToAnotherFileIsWrittenThroughAndTheLinkStays() throws IOException {
        Path real = Files.write(dir.resolve("real.png"), new byte[] {1, 2, 3});
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), real.getFileName());
        Run run = render(scene(), link);
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(link).isSymbolicLink();
        assertThat(Files.readAllBytes(real)).startsWith(PNG_SIGNATURE);
    }

    @Test
    void anOutputThatIsALinkToNothingIsAFileErrorAndTheLinkStays() throws IOException {
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), Path.of("nowhere.png"));
        Run run = render(scene(), link);
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).isEqualTo("rtd: cannot write '" + link + "': it is a symbolic link to 'nowhere.png', "
                + "which does not exist\n");
        assertThat(link).isSymbolicLink();
    }

    @Test
    void aFifoAsTheOutputGetsThePngAndStaysAFifo() throws Exception {
        Path fifo = dir.resolve("fifo.png");
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assumeThat(mkfifo.waitFor(10, TimeUnit.SECONDS) && mkfifo.exitValue() == 0).as("mkfifo works here").isTrue();
        CompletableFuture<byte[]> reader = CompletableFuture.supplyAsync(() -> {
            try (InputStream in = Files.newInputStream(fifo)) {
                return in.readAllBytes();
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        Run run = render(scene(), fifo);
        assertThat(isOther(fifo)).as("still a FIFO").isTrue();
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(reader.get(30, TimeUnit.SECONDS)).startsWith(PNG_SIGNATURE);
    }

    @Test
    void aLinkNamedAsAPictureToAFileOfAnotherKindIsRefusedAndTheFileStays() throws IOException {
        Path scene = scene();
        for (String other : new String[] {"model.obj", "notes", ".hidden", "photo.jpg"}) {
            Path file = Files.writeString(dir.resolve(other), "keep\n");
            Path link = Files.createSymbolicLink(dir.resolve("to-" + other + ".png"), file.getFileName());
            Run run = render(scene, link);
            assertThat(run.exitCode()).as(other).isEqualTo(2);
            assertThat(run.err()).as(other).contains("whose name is not that of a .png picture");
            assertThat(Files.readString(file)).as(other).isEqualTo("keep\n");
        }
    }

    @Test
    void aFifoAsTheSceneIsReadOnceAndNotRobbedOfItsFirstBytes() throws Exception {
        Path fifo = dir.resolve("scene.txt");
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assumeThat(mkfifo.waitFor(10, TimeUnit.SECONDS) && mkfifo.exitValue() == 0).as("mkfifo works here").isTrue();
        byte[] scene = Files.readAllBytes(Path.of("examples", "input_rtd.txt"));
        CompletableFuture<Void> writer = CompletableFuture.runAsync(() -> {
            try {
                Files.write(fifo, scene);
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        Run run = assertTimeoutPreemptively(Duration.ofSeconds(60),
                () -> Cli.run(fifo.toString(), "--width", "64", "--height", "36")); // a second open would wait for ever
        writer.get(10, TimeUnit.SECONDS);
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(dir.resolve("scene.png")).isRegularFile();
    }

    @Test
    void aCharacterDeviceAsTheOutputSwallowsThePngAndStaysADevice() throws Exception {
        // A copy of /dev/null (major 1, minor 3) made here: were the test to fail, it must not
        // replace the system's own /dev/null, as root may.
        Path nul = dir.resolve("null");
        Process mknod = new ProcessBuilder("mknod", nul.toString(), "c", "1", "3").start();
        assumeThat(mknod.waitFor(10, TimeUnit.SECONDS) && mknod.exitValue() == 0).as("mknod works here (root)").isTrue();
        Run run = render(scene(), nul);
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(isOther(nul)).as("still a device").isTrue();
        assertThat(Files.size(nul)).isZero();
    }

    @Test
    void aSocketAsTheOutputIsRefusedAndStaysASocket() throws IOException {
        Path socket = dir.resolve("socket.png");
        try (ServerSocketChannel server = ServerSocketChannel.open(StandardProtocolFamily.UNIX)) {
            server.bind(UnixDomainSocketAddress.of(socket));
            Run run = render(scene(), socket);
            assertThat(run.exitCode()).isEqualTo(2);
            assertThat(run.err()).startsWith("rtd: the output '" + socket + "' is a socket; rtd writes the picture to a file, "
                    + "a FIFO or a character device such as /dev/null");
            assertThat(isOther(socket)).as("still a socket").isTrue();
        }
    }

    @Test
    void theRootFolderAsTheSceneIsAFolderNotAFile() {
        Run run = Cli.run("/");
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).isEqualTo("rtd: cannot read the scene file '/': it is a folder, not a file\n");
    }
}
