package rtd.io;

import java.awt.image.DataBuffer;
import java.awt.image.DataBufferInt;
import java.awt.image.SampleModel;
import java.awt.image.SinglePixelPackedSampleModel;

/**
 * The layout of a {@link rtd.image.Picture}'s pixels for {@code javax.imageio}: one int a pixel,
 * {@code 0xRRGGBB}, row by row, as {@link SinglePixelPackedSampleModel} describes it.
 *
 * <p>The PNG writer asks for the picture a row at a time, as samples (red, green, blue of each
 * pixel in turn: {@link #getPixels}). The JDK's own answer reads each sample through the data
 * buffer's methods and the layout's masks and shifts, slow before the JIT compiles them; this
 * one reads the picture's array directly. The samples are the same.
 */
final class PackedRgbSamples extends SinglePixelPackedSampleModel {

    private static final int[] RGB_MASKS = {0xFF0000, 0xFF00, 0xFF};

    /** The layout of a {@code width × height} picture. */
    PackedRgbSamples(int width, int height) {
        super(DataBuffer.TYPE_INT, width, height, RGB_MASKS);
    }

    /** The same layout at another size: the PNG writer copies each row into a raster of its own first. */
    @Override
    public SampleModel createCompatibleSampleModel(int width, int height) {
        return new PackedRgbSamples(width, height);
    }

    @Override
    public int[] getPixels(int x, int y, int w, int h, int[] samples, DataBuffer data) {
        if (!(data instanceof DataBufferInt ints) || ints.getNumBanks() != 1 || x < 0 || y < 0 || w < 0 || h < 0
                || x + w > getWidth() || y + h > getHeight()) {
            return super.getPixels(x, y, w, h, samples, data); // as the JDK does it, with its checks
        }
        int[] into = samples != null ? samples : new int[3 * w * h];
        int[] rgb = ints.getData();
        int width = getScanlineStride();
        int k = 0;
        for (int row = y; row < y + h; row++) {
            int from = ints.getOffset() + row * width + x;
            for (int i = from; i < from + w; i++) {
                int pixel = rgb[i];
                into[k] = pixel >>> 16 & 0xFF;
                into[k + 1] = pixel >>> 8 & 0xFF;
                into[k + 2] = pixel & 0xFF;
                k += 3;
            }
        }
        return into;
    }
}
