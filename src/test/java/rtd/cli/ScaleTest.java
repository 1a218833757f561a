package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.camera.PerspectiveCamera;
import rtd.image.Color;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** {@code --scale}: the same view at another size. */
@DisplayName("The same view at another size")
class ScaleTest {

    private static final Path EXAMPLE = Path.of("examples", "input_rtd.txt");

    @TempDir
    Path dir;

    private static int[] pixels(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private Path render(String scene, String out, String... options) {
        Path output = dir.resolve(out);
        List<String> args = new java.util.ArrayList<>(List.of(scene, "-o", output.toString()));
        args.addAll(List.of(options));
        Run run = Cli.run(args.toArray(String[]::new));
        assertThat(run.exitCode()).as(run.err()).isZero();
        return output;
    }

    /** The goldens of the shaded examples are drawn as half size; this holds them to what --scale 0.5 draws. */
    @Test
    void halfSizeDrawsTheGoldensOfTheShadedExamples() throws IOException {
        for (String name : List.of("lit_paper", "smooth_mesh", "glass_and_mirror")) {
            Path half = render(Path.of("examples", name + ".txt").toString(), name + ".png", "--scale", "0.5");
            assertThat(pixels(half)).as(name).isEqualTo(pixels(Path.of("src", "test", "resources", "golden", name + ".png")));
        }
    }

    @Test
    void aQuarterIsExactlyThePictureOf480x270WithTheZoomDividedBy4InTheFile() throws IOException {
        Path zoom12 = Files.writeString(dir.resolve("zoom12.5.txt"),
                Files.readString(EXAMPLE).replace(":(50)", ":(12.5)"));
        Path scaled = render(EXAMPLE.toString(), "scaled.png", "--scale", "0.25");
        Path byHand = render(zoom12.toString(), "by_hand.png", "--width", "480", "--height", "270");
        assertThat(ImageIO.read(scaled.toFile()).getWidth()).isEqualTo(480);
        assertThat(ImageIO.read(scaled.toFile()).getHeight()).isEqualTo(270);
        assertThat(pixels(scaled)).isEqualTo(pixels(byHand));
        assertThat(Files.readAllBytes(scaled)).isEqualTo(Files.readAllBytes(byHand));
    }

    @Test
    void theScaleMultipliesAGivenSizeAndTheZoomAlike() throws IOException {
        Path zoom100 = Files.writeString(dir.resolve("zoom100.txt"), Files.readString(EXAMPLE).replace(":(50)", ":(100)"));
        Path scaled = render(EXAMPLE.toString(), "scaled.png", "--width", "300", "--height", "200", "--scale", "2");
        Path byHand = render(zoom100.toString(), "by_hand.png", "--width", "600", "--height", "400");
        assertThat(pixels(scaled)).isEqualTo(pixels(byHand));
    }

    @Test
    void thePerspectiveCameraKeepsItsFieldOfViewAndOnlyTheSizeChanges() {
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 60);
        Scene scene = new Scene(new Color(0, 0, 0), camera, List.of());
        assertThat(new Scale(0.25).of(scene).camera()).isSameAs(camera);
    }

    @Test
    void aScaleThatIsNoPositiveNumberIsMisuse() {
        for (String scale : new String[] {"0", "-1", "abc", "NaN", "Infinity", "1,5"}) {
            Run run = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("x.png").toString(), "--scale", scale);
            assertThat(run.exitCode()).as(scale).isEqualTo(2);
            assertThat(run.err()).contains("'" + scale + "' is not a number greater than 0, such as 0.25 or 2");
        }
        assertThat(Docs.errors()).contains("rtd: Invalid value for option '--scale': 'abc' is not a number greater than 0, "
                + "such as 0.25 or 2");
        assertThat(dir).isEmptyDirectory();
    }

    @Test
    void aScaleThatLeavesNoPixelIsMisuse() {
        Run run = Cli.run(EXAMPLE.toString(), "-o", dir.resolve("x.png").toString(), "--scale", "0.0001");
        assertThat(run.exitCode()).isEqualTo(2);
        String message = "rtd: --scale 0.0001 makes the 1920×1080 image 0×0 pixels; a picture needs at least one pixel "
                + "each way";
        assertThat(Docs.firstLine(run.err(), dir)).isEqualTo(message);
        assertThat(Docs.errors()).contains(message);
    }

    @Test
    void theHelpSaysHowTheScaleCombinesWithWidthAndHeight() {
        assertThat(Cli.run("--help").out().replaceAll("\\s+", " "))
                .contains("--scale=F the same view at another size: multiplies the width and height (given or default)");
    }
}
