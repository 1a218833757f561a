package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.DataBuffer;
import java.awt.image.DataBufferInt;
import java.awt.image.SinglePixelPackedSampleModel;
import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

@DisplayName("The picture's layout as the PNG writer reads it")
class PackedRgbSamplesTest {

    private static final int WIDTH = 37;
    private static final int HEIGHT = 11;

    private static DataBufferInt randomPixels(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int[] rgb = new int[WIDTH * HEIGHT];
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = random.nextInt(1 << 24);
        }
        return new DataBufferInt(rgb, rgb.length);
    }

    @Test
    void handsOutTheSameSamplesAsTheJdksOwnLayoutForEveryRectangle() {
        DataBufferInt data = randomPixels(7);
        ImageFormat.PackedRgbSamples ours = new ImageFormat.PackedRgbSamples(WIDTH, HEIGHT);
        SinglePixelPackedSampleModel jdks = new SinglePixelPackedSampleModel(DataBuffer.TYPE_INT, WIDTH, HEIGHT,
                new int[] {0xFF0000, 0xFF00, 0xFF});
        SplittableRandom random = new SplittableRandom(3);
        for (int k = 0; k < 500; k++) {
            int x = random.nextInt(WIDTH);
            int y = random.nextInt(HEIGHT);
            int w = random.nextInt(WIDTH - x + 1);
            int h = random.nextInt(HEIGHT - y + 1);
            int[] expected = jdks.getPixels(x, y, w, h, (int[]) null, data);
            assertThat(ours.getPixels(x, y, w, h, (int[]) null, data)).as("%d, %d, %d × %d", x, y, w, h)
                    .isEqualTo(expected);
            int[] given = new int[expected.length + 2];
            assertThat(ours.getPixels(x, y, w, h, given, data)).isSameAs(given);
            assertThat(Arrays.copyOf(given, expected.length)).isEqualTo(expected);
        }
    }

    @Test
    void readsAPixelsRedGreenAndBlueInThatOrder() {
        int[] rgb = new int[WIDTH * HEIGHT];
        rgb[WIDTH + 2] = 0x123456;

        int[] samples = new ImageFormat.PackedRgbSamples(WIDTH, HEIGHT).getPixels(2, 1, 1, 1, (int[]) null,
                new DataBufferInt(rgb, rgb.length));

        assertThat(samples).containsExactly(0x12, 0x34, 0x56);
    }

    @Test
    void refusesARectangleOutsideThePictureAsTheJdkDoes() {
        ImageFormat.PackedRgbSamples ours = new ImageFormat.PackedRgbSamples(WIDTH, HEIGHT);
        DataBufferInt data = randomPixels(1);

        assertThatThrownBy(() -> ours.getPixels(WIDTH - 3, 0, 4, 1, (int[]) null, data))
                .isInstanceOf(ArrayIndexOutOfBoundsException.class);
    }

    @Test
    void aLayoutOfAnotherSizeIsOfTheSameKind() {
        assertThat(new ImageFormat.PackedRgbSamples(WIDTH, HEIGHT).createCompatibleSampleModel(5, 1))
                .isInstanceOf(ImageFormat.PackedRgbSamples.class).returns(5, s -> s.getWidth()).returns(1, s -> s.getHeight());
    }
}
