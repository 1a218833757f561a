package rtd.scene;

import java.util.ArrayList;
import java.util.List;
import rtd.image.Rgb;
import rtd.math.Vector3f;

/**
 * A light that shines from a parallelogram, for soft shadows without randomness (Part III, "Area
 * lights"): the corner C and the edges u and v span it, and it lights exactly as the {@code n·m}
 * point lights of {@link #samples}, each with its own shadow ray, so a point that sees part of
 * the parallelogram gets part of its light, the same on every run. Like a point light it is not
 * seen itself. An edge of length 0 makes a line of lights, two make a point.
 *
 * @param corner    C, a corner of the parallelogram
 * @param u         the edge from C along which {@code n} samples lie
 * @param v         the edge from C along which {@code m} samples lie
 * @param n         how many samples along u, 1 to 32
 * @param m         how many samples along v, 1 to 32
 * @param intensity the whole light's colour and brightness, shared out among the samples
 */
public record AreaLight(Vector3f corner, Vector3f u, Vector3f v, int n, int m, Rgb intensity) {

    /** The most samples along an edge: 32 × 32 shadow rays a point are plenty for a soft shadow. */
    public static final int MOST_SAMPLES = 32;

    /** Checks the sample counts. */
    public AreaLight {
        if (n < 1 || n > MOST_SAMPLES || m < 1 || m > MOST_SAMPLES) {
            throw new IllegalArgumentException("an area light takes 1 to 32 samples along each edge, not "
                    + n + " × " + m);
        }
    }

    /**
     * The point lights it is: for {@code i < n}, {@code j < m} (i outer), one at the centre of
     * its cell, {@code C + (i + ½)/n·u + (j + ½)/m·v}, of intensity {@code I/(n·m)}; each knows it
     * is a sample of this light ({@link Light#area}).
     */
    public List<Light> samples() {
        Rgb share = new Rgb(intensity.red() / (n * m), intensity.green() / (n * m), intensity.blue() / (n * m));
        List<Light> samples = new ArrayList<>(n * m);
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < m; j++) {
                Vector3f position = corner.add(u.multiply((i + 0.5f) / n)).add(v.multiply((j + 0.5f) / m));
                samples.add(new Light(position, share, this));
            }
        }
        return List.copyOf(samples);
    }

    /** How many point lights it is: {@code n·m}. */
    public int sampleCount() {
        return n * m;
    }
}
