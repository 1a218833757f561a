package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.assertj.core.api.Assumptions.assumeThat;

import java.io.IOException;
import java.io.OutputStream;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** Reading a scene file that never ends, is huge, or is not text: bounded memory and time. */
@DisplayName("Reading a scene file")
class SceneIOTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";

    @TempDir
    Path dir;

    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS) // a guard against reading forever, not a measure of speed
    void devZeroStopsAtItsFirstNulByteWithALocatedError() {
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneIO.readScene(Path.of("/dev/zero")));
        assertThat(e).as("a SceneException").isNotNull();
        assertThat(e.errors()).hasSize(1);
        assertThat(e.errors().get(0).format()).startsWith("/dev/zero:1:1: error: this is not a text file: found a NUL byte\n");
    }

    @Test
    void aFileLargerThanTheLimitIsRefusedBeforeReadingWithItsNameAndSize() throws IOException {
        Path huge = dir.resolve("huge.txt");
        try (RandomAccessFile file = new RandomAccessFile(huge.toFile(), "rw")) {
            file.setLength(3L << 30); // sparse: no disk, no time
        }
        FileSystemException e = catchThrowableOfType(FileSystemException.class, () -> SceneIO.readScene(huge));
        assertThat(e).as("a FileSystemException").isNotNull();
        assertThat(e.getFile()).isEqualTo(huge.toString());
        assertThat(e.getReason()).startsWith("it is 3.0 GiB; rtd reads scene files of at most 1.0 GiB");
    }

    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS)
    void aStreamOfTextThatNeverEndsIsRefusedOnceItPassesTheLimit() throws Exception {
        Path fifo = dir.resolve("fifo.txt");
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assumeThat(mkfifo.waitFor(10, TimeUnit.SECONDS) && mkfifo.exitValue() == 0).as("mkfifo works here").isTrue();
        Thread writer = new Thread(() -> {
            byte[] blanks = "   // an endless comment\n".repeat(1000).getBytes(StandardCharsets.US_ASCII);
            try (OutputStream out = Files.newOutputStream(fifo)) {
                while (true) {
                    out.write(blanks);
                }
            } catch (IOException e) {
                // the reader stopped reading: the end we wait for
            }
        });
        writer.setDaemon(true);
        writer.start();
        FileSystemException e = catchThrowableOfType(FileSystemException.class, () -> SceneIO.readBytes(fifo, 1 << 20));
        assertThat(e).as("a FileSystemException").isNotNull();
        assertThat(e.getReason()).startsWith("it is larger than 1.0 MiB; rtd reads scene files of at most 1.0 MiB");
    }

    @Test
    void aCharacterCutByTheEndOfAChunkIsTextAndALaterBadByteIsLocated() throws Exception {
        // "é" (2 bytes) across the boundary of the reader's chunks of 65,536 bytes.
        String comment = "//" + "x".repeat((1 << 16) - 1 - CAMERA.length() - 2) + "é\n";
        String text = CAMERA + comment + "sphere:(0|0|0):(1):(1|2|3)\n".repeat(3000);
        assertThat((CAMERA + comment).getBytes(StandardCharsets.UTF_8)[(1 << 16) - 1]).isEqualTo((byte) 0xC3);
        Path good = Files.writeString(dir.resolve("good.txt"), text);
        assertThat(SceneIO.readScene(good).objects()).hasSize(3000);

        byte[] valid = text.getBytes(StandardCharsets.UTF_8);
        byte[] bad = java.util.Arrays.copyOf(valid, valid.length + 5);
        System.arraycopy(new byte[] {'/', '/', ' ', (byte) 0xFF, '\n'}, 0, bad, valid.length, 5);
        Path latin1 = Files.write(dir.resolve("latin1.txt"), bad);
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneIO.readScene(latin1));
        assertThat(e.errors().get(0).format()).startsWith(latin1 + ":3003:4: error: the file is not UTF-8 but looks like Latin-1 (ISO-8859-1) or Windows-1252: "
                + "found byte 0xFF, which is '\u00ff' there");
    }
}
