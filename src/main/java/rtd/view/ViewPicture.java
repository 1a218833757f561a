package rtd.view;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import rtd.geometry.IGeometry;
import rtd.image.Picture;
import rtd.scene.Scene;

/**
 * Turns the numbers a {@link ViewShader} left in a picture into colours, with the view's scale
 * in a {@link Legend} below the picture and in words ({@link #report}).
 *
 * <ul>
 * <li>cost: a heat map on a logarithmic scale from 0 to N tests, N the scene's number of
 *     objects: the most the paper's loop (Listing 4.3) takes, so that the pictures of one scene
 *     with each {@code --accel} share one scale and can be set side by side;</li>
 * <li>depth: grey from white at the nearest hit of the picture to dark grey at the farthest; no
 *     hit is black. Where the farthest hits lie more than twice as far as 90 % of them (an open
 *     floor running to the horizon), the scale ends at that 90 %, and the hits beyond are dark
 *     grey too, so that the scene's objects are not all white. The scale is the picture's own,
 *     so it is the same for every run;</li>
 * <li>normal, id: the colours as the shader made them.</li>
 * </ul>
 *
 * @param picture the picture to write
 * @param report  the scale and a summary, for standard error
 */
public record ViewPicture(Picture picture, String report) {

    private static final int FAR_GREY = 48;
    /** The share of the hits the depth scale spans when the farthest lie far beyond them. */
    private static final double MOST_HITS = 0.9;
    /** How far beyond {@link #MOST_HITS} of the hits the farthest must lie for the scale to stop there. */
    private static final float LONG_TAIL = 2;

    /** The picture of {@code view} from the shader's numbers {@code raw}, a render of {@code scene}. */
    public static ViewPicture of(View view, Picture raw, Scene scene) {
        return switch (view) {
            case cost -> cost(raw, scene.objects().size());
            case depth -> depth(raw);
            case normal -> new ViewPicture(raw,
                    "normal: red, green, blue = (N + 1)/2 of the unit normal's x, y, z; no hit: black\n");
            case id -> new ViewPicture(raw, idReport(scene.objects()));
        };
    }

    private static ViewPicture cost(Picture raw, int objects) {
        int[] counts = raw.rgb();
        long total = 0;
        int max = 0;
        for (int count : counts) {
            total += count;
            max = Math.max(max, count);
        }
        int top = Math.max(1, objects);
        double logTop = Math.log1p(top);
        int[] rgb = new int[counts.length];
        for (int i = 0; i < counts.length; i++) {
            rgb[i] = ViewColours.heat(Math.log1p(counts[i]) / logTop);
        }
        List<Legend.Tick> ticks = new ArrayList<>();
        for (long value = 1; value < top; value *= 10) {
            ticks.add(new Legend.Tick(Math.log1p(value) / logTop, Long.toString(value)));
        }
        ticks.add(0, new Legend.Tick(0, "0"));
        ticks.add(new Legend.Tick(1, top + " tests"));
        Picture picture = Legend.below(new Picture(raw.width(), raw.height(), rgb), ViewColours::heat, ticks);
        String report = String.format(Locale.ROOT,
                "cost: intersection tests per camera ray, colours on a logarithmic scale from 0 (black) to %d, "
                        + "the scene's number of objects (pale yellow)%n"
                        + "this picture: %,d tests for %,d rays, %.2f per ray, at most %d%n",
                top, total, counts.length, (double) total / counts.length, max);
        return new ViewPicture(picture, report);
    }

    private static ViewPicture depth(Picture raw) {
        float[] hits = hitDistances(raw.rgb());
        if (hits.length == 0) {
            return new ViewPicture(new Picture(raw.width(), raw.height(), new int[raw.rgb().length]),
                    "depth: no ray hits anything; all black\n");
        }
        float near = hits[0];
        float farthest = hits[hits.length - 1];
        float most = hits[(int) ((hits.length - 1) * MOST_HITS)];
        boolean tail = farthest > LONG_TAIL * most; // an open floor or a far backdrop would leave the rest all white
        float far = tail ? most : farthest;
        int[] rgb = new int[raw.rgb().length];
        for (int i = 0; i < rgb.length; i++) {
            float distance = Float.intBitsToFloat(raw.rgb()[i]);
            rgb[i] = Float.isFinite(distance)
                    ? grey(far > near ? Math.min(1, (distance - near) / (double) (far - near)) : 0)
                    : 0;
        }
        List<Legend.Tick> ticks = List.of(new Legend.Tick(0, label(near)),
                new Legend.Tick(1, label(far) + (tail ? "+" : "")));
        Picture picture = Legend.below(new Picture(raw.width(), raw.height(), rgb), ViewPicture::grey, ticks);
        String scale = tail ? String.format(Locale.ROOT,
                "dark grey at %s, which %d %% of the hits are nearer than (the "
                + "farthest, at %s, are dark grey too)", label(far), Math.round(MOST_HITS * 100), label(farthest))
                : String.format(Locale.ROOT, "dark grey at %s (the farthest)", label(far));
        String report = String.format(Locale.ROOT, "depth: |P − O| of each camera ray's nearest hit, white at %s (the "
                + "nearest in the picture) to %s; no hit: black%n", label(near), scale);
        return new ViewPicture(picture, report);
    }

    /** The finite distances of the picture's hits, sorted. */
    private static float[] hitDistances(int[] raw) {
        float[] hits = new float[raw.length];
        int count = 0;
        for (int bits : raw) {
            float distance = Float.intBitsToFloat(bits);
            if (Float.isFinite(distance)) {
                hits[count++] = distance;
            }
        }
        float[] sorted = Arrays.copyOf(hits, count);
        Arrays.sort(sorted);
        return sorted;
    }

    /** White at share 0 (near), dark grey at 1 (far). */
    private static int grey(double share) {
        int level = (int) Math.round(255 - share * (255 - FAR_GREY));
        return (level << 16) | (level << 8) | level;
    }

    private static String label(float distance) {
        return String.format(Locale.ROOT, "%.4g", distance);
    }

    private static String idReport(List<IGeometry> objects) {
        StringBuilder text = new StringBuilder("id: one colour per object, in file order; no hit: black\n");
        for (int i = 0; i < Math.min(objects.size(), 20); i++) {
            int rgb = ViewColours.id(i);
            text.append(String.format(Locale.ROOT, "  #%d %s: (%d|%d|%d)%n", i + 1, objects.get(i).kind(), rgb >> 16,
                    (rgb >> 8) & 0xFF, rgb & 0xFF));
        }
        if (objects.size() > 20) {
            text.append(String.format(Locale.ROOT, "  ... and %,d more%n", objects.size() - 20));
        }
        return text.toString();
    }
}
