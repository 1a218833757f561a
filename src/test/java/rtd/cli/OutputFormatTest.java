package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.camera.OrthographicCamera;
import rtd.io.SceneIO;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** The output's extension chooses the picture's format, through javax.imageio. */
@DisplayName("The format of the picture")
class OutputFormatTest {

    private static final Path EXAMPLE = Path.of("examples", "input_rtd.txt");

    @TempDir
    Path dir;

    private static int[] pixels(BufferedImage image) {
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }

    private Path render(String name) {
        Path out = dir.resolve(name);
        Run run = Cli.run(EXAMPLE.toString(), "-o", out.toString(), "--scale", "0.1");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).isEmpty();
        return out;
    }

    @Test
    void aPngDecodesToExactlyThePixelsOfThePapersOwnRenderer() throws Exception {
        Scene example = SceneIO.readScene(EXAMPLE);
        BufferedImage paper = new Scene(example.ambient(), new OrthographicCamera(new Vector3f(0, 0, 20),
                new Vector3f(0, 0, -1), 5), example.objects()).render(192, 108);
        assertThat(pixels(ImageIO.read(render("out.png").toFile()))).isEqualTo(pixels(paper));
    }

    @Test
    void aJpgNameGetsAJpegNotPngBytes() throws IOException {
        assertThat(Files.readAllBytes(render("out.jpg"))).startsWith(0xFF, 0xD8, 0xFF);
        assertThat(Files.readAllBytes(render("OUT.JPEG"))).startsWith(0xFF, 0xD8, 0xFF);
        assertThat(ImageIO.read(dir.resolve("out.jpg").toFile()).getWidth()).isEqualTo(192);
    }

    @Test
    void aBmpNameGetsABitmapOfTheSamePixelsAsThePng() throws IOException {
        Path bmp = render("out.bmp");
        assertThat(Files.readAllBytes(bmp)).startsWith('B', 'M');
        assertThat(pixels(ImageIO.read(bmp.toFile()))).isEqualTo(pixels(ImageIO.read(render("out.png").toFile())));
    }

    @Test
    void aNameWithoutExtensionGetsAPng() throws IOException {
        assertThat(Files.readAllBytes(render("picture"))).startsWith(0x89, 'P', 'N', 'G');
    }

    @Test
    void anExtensionThatNoWriterKnowsIsMisuseThatListsTheWritableOnesAndWritesNothing() {
        Path out = dir.resolve("out.xyz");
        Run run = Cli.run(EXAMPLE.toString(), "-o", out.toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).startsWith("rtd: the output '" + out + "' ends in '.xyz', a format rtd cannot write; "
                + "give it one of .bmp, ").contains(".jpeg, .jpg, .png").doesNotContain(".wbmp")
                .endsWith("Try 'java -jar rtd.jar --help' for more information.\n");
        assertThat(dir).isEmptyDirectory();
        assertThat(Docs.errors()).contains("rtd: the output 'out.xyz' ends in '.xyz', a format rtd cannot write; "
                + "give it one of .bmp, ");
    }

    @Test
    void anUnwritableExtensionIsFoundBeforeTheSceneIsRead() {
        Run run = Cli.run(dir.resolve("missing.txt").toString(), "-o", dir.resolve("out.xyz").toString());
        assertThat(run.exitCode()).as("the command line, not the missing file").isEqualTo(2);
    }
}
