package rtd.io;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.awt.image.IndexColorModel;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import rtd.image.Picture;

/**
 * Reduces a picture to the 256 colours a GIF frame holds: a palette by median cut (Heckbert, 1982) of the
 * frame's own colours, each the mean of the pixels it stands for; a pixel of a palette colour keeps it (a
 * flat scene of few colours stays exact), any other is mapped to its nearest palette colour after an ordered
 * dither (an 8 × 8 Bayer matrix) of up to one step of the 32 levels per channel the palette is looked up by.
 * An ordered dither
 * depends on the pixel's place only, not on its neighbours, so a part of the picture that does not move keeps
 * its pattern from frame to frame instead of crawling, as error diffusion would make it.
 */
final class GifPalette {

    private static final int LEVELS = 32;
    private static final int[] BAYER = bayer();

    private GifPalette() {
    }

    /** The picture as an indexed image of at most 256 colours. */
    static BufferedImage reduce(Picture picture) {
        return reduce(picture, palette(picture.rgb()), true);
    }

    /** The picture in {@code palette} (packed RGB), dithered or not. */
    static BufferedImage reduce(Picture picture, int[] palette, boolean dither) {
        int[] nearest = nearestTable(palette);
        java.util.Map<Integer, Integer> exact = new java.util.HashMap<>();
        for (int k = 0; k < palette.length; k++) {
            exact.putIfAbsent(palette[k], k);
        }
        int w = picture.width();
        byte[] indices = new byte[w * picture.height()];
        int[] rgb = picture.rgb();
        for (int i = 0; i < rgb.length; i++) {
            Integer same = exact.get(rgb[i] & 0xFFFFFF);
            if (same != null) {
                indices[i] = (byte) (int) same;
                continue;
            }
            int offset = dither ? BAYER[(i / w % 8) * 8 + i % w % 8] : 4; // 4: half a step, plain rounding
            int r = Math.min(255, ((rgb[i] >> 16) & 0xFF) + offset) >> 3;
            int g = Math.min(255, ((rgb[i] >> 8) & 0xFF) + offset) >> 3;
            int b = Math.min(255, (rgb[i] & 0xFF) + offset) >> 3;
            indices[i] = (byte) nearest[(r << 10) | (g << 5) | b];
        }
        byte[][] channels = new byte[3][palette.length];
        for (int k = 0; k < palette.length; k++) {
            channels[0][k] = (byte) (palette[k] >> 16);
            channels[1][k] = (byte) (palette[k] >> 8);
            channels[2][k] = (byte) palette[k];
        }
        IndexColorModel model = new IndexColorModel(8, palette.length, channels[0], channels[1], channels[2]);
        BufferedImage image = new BufferedImage(w, picture.height(), BufferedImage.TYPE_BYTE_INDEXED, model);
        byte[] data = ((DataBufferByte) image.getRaster().getDataBuffer()).getData();
        System.arraycopy(indices, 0, data, 0, indices.length);
        return image;
    }

    /** A palette of at most 256 colours for {@code rgb}, by median cut of its colours at 32 levels per channel. */
    static int[] palette(int[] rgb) {
        int[] counts = new int[LEVELS * LEVELS * LEVELS];
        long[][] sums = new long[3][counts.length];
        for (int c : rgb) {
            int bin = ((c >> 19) & 0x1F) << 10 | ((c >> 11) & 0x1F) << 5 | ((c >> 3) & 0x1F);
            counts[bin]++;
            sums[0][bin] += (c >> 16) & 0xFF;
            sums[1][bin] += (c >> 8) & 0xFF;
            sums[2][bin] += c & 0xFF;
        }
        List<int[]> boxes = new ArrayList<>();
        int[] all = new int[counts.length];
        int n = 0;
        for (int bin = 0; bin < counts.length; bin++) {
            if (counts[bin] > 0) {
                all[n++] = bin;
            }
        }
        boxes.add(java.util.Arrays.copyOf(all, n));
        while (boxes.size() < 256) {
            int[] widest = boxes.stream().filter(box -> box.length > 1).max(Comparator.comparingInt(GifPalette::range))
                    .orElse(null);
            if (widest == null) {
                break;
            }
            boxes.remove(widest);
            boxes.addAll(split(widest, counts));
        }
        int[] palette = new int[Math.max(2, boxes.size())]; // an IndexColorModel needs at least 2 entries
        for (int k = 0; k < boxes.size(); k++) {
            palette[k] = mean(boxes.get(k), counts, sums);
        }
        return palette;
    }

    /** The box's longest side, in levels. */
    private static int range(int[] box) {
        int best = 0;
        for (int axis = 0; axis < 3; axis++) {
            int low = LEVELS;
            int high = -1;
            for (int bin : box) {
                int v = (bin >> (10 - 5 * axis)) & 0x1F;
                low = Math.min(low, v);
                high = Math.max(high, v);
            }
            best = Math.max(best, high - low);
        }
        return best;
    }

    /** The box cut in two along its longest side, where half its pixels lie on either side. */
    private static List<int[]> split(int[] box, int[] counts) {
        int axis = 0;
        int widest = -1;
        for (int a = 0; a < 3; a++) {
            int shift = 10 - 5 * a;
            int low = java.util.Arrays.stream(box).map(bin -> (bin >> shift) & 0x1F).min().orElse(0);
            int high = java.util.Arrays.stream(box).map(bin -> (bin >> shift) & 0x1F).max().orElse(0);
            if (high - low > widest) {
                widest = high - low;
                axis = a;
            }
        }
        int shift = 10 - 5 * axis;
        int[] sorted = java.util.Arrays.stream(box).boxed().sorted(Comparator.comparingInt(bin -> (bin >> shift) & 0x1F))
                .mapToInt(Integer::intValue).toArray();
        long total = 0;
        for (int bin : sorted) {
            total += counts[bin];
        }
        long half = 0;
        int cut = 0;
        while (cut < sorted.length - 1 && half + counts[sorted[cut]] <= total / 2) {
            half += counts[sorted[cut++]];
        }
        cut = Math.max(1, cut);
        return List.of(java.util.Arrays.copyOfRange(sorted, 0, cut), java.util.Arrays.copyOfRange(sorted, cut, sorted.length));
    }

    /** The mean colour of the box's pixels, rounded. */
    private static int mean(int[] box, int[] counts, long[][] sums) {
        long r = 0;
        long g = 0;
        long b = 0;
        long n = 0;
        for (int bin : box) {
            r += sums[0][bin];
            g += sums[1][bin];
            b += sums[2][bin];
            n += counts[bin];
        }
        return (int) ((r + n / 2) / n) << 16 | (int) ((g + n / 2) / n) << 8 | (int) ((b + n / 2) / n);
    }

    /** For each bin of 32 levels per channel, the index of the nearest palette colour to its centre. */
    private static int[] nearestTable(int[] palette) {
        int[] table = new int[LEVELS * LEVELS * LEVELS];
        for (int bin = 0; bin < table.length; bin++) {
            int r = ((bin >> 10) & 0x1F) * 8 + 4;
            int g = ((bin >> 5) & 0x1F) * 8 + 4;
            int b = (bin & 0x1F) * 8 + 4;
            int best = 0;
            int bestDistance = Integer.MAX_VALUE;
            for (int k = 0; k < palette.length; k++) {
                int dr = r - ((palette[k] >> 16) & 0xFF);
                int dg = g - ((palette[k] >> 8) & 0xFF);
                int db = b - (palette[k] & 0xFF);
                int distance = dr * dr + dg * dg + db * db;
                if (distance < bestDistance) {
                    bestDistance = distance;
                    best = k;
                }
            }
            table[bin] = best;
        }
        return table;
    }

    /** The 8 × 8 Bayer matrix as offsets 0 … 7 of the 8 values a level of 32 spans. */
    private static int[] bayer() {
        int[] matrix = new int[64];
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 8; x++) {
                int v = 0;
                int xc = x ^ y;
                for (int bit = 2; bit >= 0; bit--) { // interleave the bits of y and x ^ y, high first
                    v = v << 2 | ((xc >> bit) & 1) << 1 | ((y >> bit) & 1);
                }
                matrix[y * 8 + x] = v / 8; // 0 … 63 to 0 … 7
            }
        }
        return matrix;
    }
}
