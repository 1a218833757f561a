package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.zip.CRC32;
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import rtd.image.Picture;

@DisplayName("The PNG encoder")
class PngEncoderTest {

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

    static byte[] encode(Picture picture, int threads) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PngEncoder.write(picture, out, threads);
        return out.toByteArray();
    }

    @ParameterizedTest(name = "{0} × {1}")
    @CsvSource({"1, 1", "7, 3", "320, 64", "320, 65", "200, 130", "1920, 1080"})
    void writesAPngThatJavasOwnReaderDecodesToTheSamePixels(int width, int height) throws IOException {
        Picture picture = picture(width, height, width * 31L + height);
        BufferedImage decoded = ImageIO.read(new ByteArrayInputStream(encode(picture, 2)));
        assertThat(decoded.getWidth()).isEqualTo(width);
        assertThat(decoded.getHeight()).isEqualTo(height);
        int[] pixels = decoded.getRGB(0, 0, width, height, null, 0, width);
        for (int i = 0; i < pixels.length; i++) {
            pixels[i] &= 0xFFFFFF;
        }
        assertThat(pixels).isEqualTo(picture.rgb());
    }

    @Test
    void writesTheSameBytesForAnyNumberOfThreads() throws IOException {
        Picture picture = picture(500, 300, 7);
        byte[] one = encode(picture, 1);
        assertThat(encode(picture, 2)).isEqualTo(one);
        assertThat(encode(picture, 5)).isEqualTo(one);
        assertThat(encode(picture, 64)).isEqualTo(one);
    }

    @Test
    void hasCorrectChunkChecksumsAndAZlibStreamWithAValidAdler32() throws IOException, DataFormatException {
        Picture picture = picture(100, 150, 3);
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(encode(picture, 3)));
        byte[] signature = new byte[8];
        in.readFully(signature);
        assertThat(signature).containsExactly(0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n');
        List<String> types = new ArrayList<>();
        ByteArrayOutputStream zlib = new ByteArrayOutputStream();
        while (in.available() > 0) {
            byte[] data = new byte[in.readInt()];
            byte[] type = new byte[4];
            in.readFully(type);
            in.readFully(data);
            CRC32 crc = new CRC32();
            crc.update(type);
            crc.update(data);
            assertThat(in.readInt()).as("CRC of a chunk").isEqualTo((int) crc.getValue());
            String name = new String(type, StandardCharsets.US_ASCII);
            types.add(name);
            if (name.equals("IDAT")) {
                zlib.write(data);
            }
        }
        assertThat(types.get(0)).isEqualTo("IHDR");
        assertThat(types.subList(1, types.size() - 1)).hasSize(3).containsOnly("IDAT");
        assertThat(types.get(types.size() - 1)).isEqualTo("IEND");

        Inflater inflater = new Inflater(); // checks the Adler-32 at the end of the stream
        inflater.setInput(zlib.toByteArray());
        byte[] rows = new byte[150 * (1 + 3 * 100) + 1];
        int length = 0;
        while (!inflater.finished()) {
            length += inflater.inflate(rows, length, rows.length - length);
        }
        assertThat(length).isEqualTo(150 * (1 + 3 * 100));
        assertThat(rows[0]).as("filter type of the first row").isZero();
        int pixel = picture.rgb(1, 0);
        assertThat(new int[] {rows[4] & 0xFF, rows[5] & 0xFF, rows[6] & 0xFF})
                .containsExactly(pixel >> 16 & 0xFF, pixel >> 8 & 0xFF, pixel & 0xFF);
    }
}
