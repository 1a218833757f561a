package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import rtd.image.Picture;

@DisplayName("Writing the picture through javax.imageio")
class ImageFormatTest {

    /** Flat areas, as rtd draws them, with a few random pixels so that no two rows are alike. */
    static Picture picture(int width, int height, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int[] rgb = new int[width * height];
        for (int i = 0; i < rgb.length; i++) {
            int x = i % width;
            rgb[i] = random.nextInt(50) == 0 ? random.nextInt(1 << 24) : x < width / 3 ? 0x102030 : 0xFFEE00;
        }
        return new Picture(width, height, rgb);
    }

    static byte[] encode(Picture picture, String extension) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        new ImageFormat(extension).write(picture, out, fraction -> { });
        return out.toByteArray();
    }

    static int[] decodedPixels(byte[] file) throws IOException {
        BufferedImage decoded = ImageIO.read(new ByteArrayInputStream(file));
        int[] pixels = decoded.getRGB(0, 0, decoded.getWidth(), decoded.getHeight(), null, 0, decoded.getWidth());
        for (int i = 0; i < pixels.length; i++) {
            pixels[i] &= 0xFFFFFF;
        }
        return pixels;
    }

    @ParameterizedTest(name = "{0} × {1}")
    @CsvSource({"1, 1", "7, 3", "320, 64", "320, 65", "200, 130", "1920, 1080"})
    void aPngDecodesToExactlyThePicturesPixels(int width, int height) throws IOException {
        Picture picture = picture(width, height, width * 31L + height);
        byte[] png = encode(picture, "png");
        assertThat(png).startsWith(0x89, 'P', 'N', 'G');
        assertThat(decodedPixels(png)).isEqualTo(picture.rgb());
    }

    @Test
    void aBmpDecodesToExactlyThePicturesPixels() throws IOException {
        Picture picture = picture(101, 37, 5);
        byte[] bmp = encode(picture, "bmp");
        assertThat(bmp).startsWith('B', 'M');
        assertThat(decodedPixels(bmp)).isEqualTo(picture.rgb());
    }

    @Test
    void aJpegIsAJpegWhoseFlatAreasKeepTheirColourNearly() throws IOException {
        int[] rgb = new int[64 * 64];
        java.util.Arrays.fill(rgb, 0x3080C0);
        byte[] jpeg = encode(new Picture(64, 64, rgb), "jpg");
        assertThat(jpeg).startsWith(0xFF, 0xD8, 0xFF);
        int pixel = decodedPixels(jpeg)[32 * 64 + 32];
        assertThat(pixel >> 16 & 0xFF).isBetween(0x30 - 4, 0x30 + 4);
        assertThat(pixel >> 8 & 0xFF).isBetween(0x80 - 4, 0x80 + 4);
        assertThat(pixel & 0xFF).isBetween(0xC0 - 4, 0xC0 + 4);
    }

    @Test
    void tellsTheFractionWrittenUpToTheWhole() throws IOException {
        List<Double> fractions = new ArrayList<>();
        ImageFormat.PNG.write(picture(50, 40, 1), new ByteArrayOutputStream(), fractions::add);
        assertThat(fractions).isNotEmpty().isSorted().last().isEqualTo(1.0);
    }

    @Test
    void theWarmUpLoadsTheWriterWithoutError() {
        assertThat(ImageFormat.PNG.warmUp(() -> { })).succeedsWithin(java.time.Duration.ofSeconds(30));
    }

    @Test
    void theFormatFollowsTheExtensionInAnyCaseAndIsPngWithoutOne() {
        assertThat(ImageFormat.forOutput(Path.of("a/out.PNG"))).contains(ImageFormat.PNG);
        assertThat(ImageFormat.forOutput(Path.of("out"))).contains(ImageFormat.PNG);
        assertThat(ImageFormat.forOutput(Path.of(".hidden"))).contains(ImageFormat.PNG);
        assertThat(ImageFormat.forOutput(Path.of("-"))).contains(ImageFormat.PNG);
        assertThat(ImageFormat.forOutput(Path.of("x.Jpeg"))).contains(new ImageFormat("jpeg"));
        assertThat(ImageFormat.forOutput(Path.of("x.bmp"))).contains(new ImageFormat("bmp"));
        assertThat(ImageFormat.forOutput(Path.of("x.xyz"))).isEmpty();
        assertThat(ImageFormat.forOutput(Path.of("x.wbmp"))).as("black and white only").isEmpty();
    }

    @Test
    void offersEveryExtensionThatJavaxImageioWritesInColourAndNoOther() {
        assertThat(ImageFormat.writableExtensions()).contains("png", "jpg", "jpeg", "bmp").doesNotContain("wbmp")
                .isSorted();
    }
}
