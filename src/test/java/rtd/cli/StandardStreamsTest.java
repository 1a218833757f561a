package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code -} reads the scene from standard input; {@code -o -} writes the picture to standard output. */
@DisplayName("Standard input and output")
class StandardStreamsTest {

    private static final Path EXAMPLE = Path.of("examples", "input_rtd.txt");
    private static final byte[] NOTHING = new byte[0];

    @TempDir
    Path dir;

    @Test
    void aDashReadsTheSceneFromStandardInput() throws IOException {
        Path out = dir.resolve("out.png");
        StreamRun run = StreamRun.run(Files.readAllBytes(EXAMPLE), false, "-", "-o", out.toString(), "--scale", "0.1");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(ImageIO.read(out.toFile()).getRGB(46, 49) & 0xFFFFFF).isEqualTo(0xFF0000);
    }

    @Test
    void aMistakeInAStandardInputSceneIsNamedAsStdin() {
        StreamRun run = StreamRun.run("spere:(1|2|3):(1):(0|0|0)\n".getBytes(), false, "-", "-o",
                dir.resolve("out.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).startsWith("<stdin>:1:1: error: unknown statement 'spere'");
    }

    @Test
    void aDashWithoutAnOutputIsMisuse() {
        StreamRun run = StreamRun.run(NOTHING, false, "-");
        assertThat(run.exitCode()).isEqualTo(2);
        String message = "rtd: the scene '-' comes from standard input, which gives no name for the picture; name it with "
                + "-o, such as -o out.png, or -o - for standard output";
        assertThat(run.err()).startsWith(message + "\n");
        assertThat(Docs.errors()).contains(message);
    }

    @Test
    void aDashAsTheOutputWritesAPngToStandardOutput() throws IOException {
        StreamRun run = StreamRun.run(NOTHING, false, EXAMPLE.toString(), "-o", "-", "--scale", "0.1");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.out()).startsWith(0x89, 'P', 'N', 'G');
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(run.out()));
        assertThat(image.getWidth()).isEqualTo(192);
        assertThat(run.err()).isEmpty();
    }

    @Test
    void standardInToStandardOutWorksAsAFilter() {
        StreamRun run = StreamRun.run(
                "orthographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(0|0|0):(1):(255|0|0)\n".getBytes(), false, "-", "-o",
                "-", "--width", "8", "--height", "8");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.out()).startsWith(0x89, 'P', 'N', 'G');
    }

    @Test
    void aTerminalAsStandardOutputIsRefusedBeforeAnyWork() {
        StreamRun run = StreamRun.run(NOTHING, true, EXAMPLE.toString(), "-o", "-");
        assertThat(run.exitCode()).isEqualTo(2);
        String message = "rtd: -o - writes the picture to standard output, which is a terminal here; send it to a file "
                + "or a program instead, such as: java -jar rtd.jar scene.txt -o - > out.png";
        assertThat(run.err()).startsWith(message + "\n");
        assertThat(Docs.errors()).contains(message);
        assertThat(run.out()).isEmpty();
    }

    @Test
    void aReaderThatStopsEarlyIsNamedAsTheCauseOfABrokenPipe() {
        java.io.OutputStream closed = new java.io.OutputStream() {
            @Override
            public void write(int b) throws IOException {
                throw new IOException("Broken pipe"); // what the JVM says when the reader of a pipe has gone
            }
        };
        StandardStreams streams = new StandardStreams(new ByteArrayInputStream(NOTHING), java.util.Optional.empty(),
                false, closed, false);
        java.io.StringWriter err = new java.io.StringWriter();
        picocli.CommandLine commandLine = RtdCommand.commandLine(streams);
        commandLine.setErr(new java.io.PrintWriter(err, true));
        int exitCode = commandLine.execute(EXAMPLE.toString(), "-o", "-", "--scale", "0.1");
        assertThat(exitCode).isEqualTo(1);
        assertThat(err.toString()).startsWith("rtd: cannot write the picture to standard output: the program reading it "
                + "stopped before the end (broken pipe)");
    }
}
