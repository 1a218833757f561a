package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Vector3f;

/** The footprints of a sample of the objects, which the view grid measures first to choose its cells. */
@DisplayName("A sample of footprints")
class ImageFootprintTest {

    private static final ImageFootprint FOOTPRINT = ImageFootprint.of(
            new PerspectiveCamera(new Vector3f(0, 0, 10), new Vector3f(0, 0, -1), 60), 64, 48, 0);

    /** Ten spheres in a row across the view, the last ones beside it. */
    private static List<IGeometry> row(int count) {
        List<IGeometry> spheres = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            spheres.add(new Sphere(new Vector3f(-4 + 1.5f * i, 0, 0), 0.5f, new Color(255, 0, 0)));
        }
        return spheres;
    }

    private static int[] footprintOf(IGeometry object) {
        int[] footprint = new int[4];
        FOOTPRINT.putObject(object, new float[6], footprint, 0);
        return footprint;
    }

    @Test
    void holdsTheFootprintOfEveryStepThObjectFromTheFirstAsPutObjectWritesIt() {
        List<IGeometry> spheres = row(10);

        int[] sample = FOOTPRINT.ofSample(spheres, 4); // a step of 10 / 4 = 2: objects 0, 2, 4, 6, 8

        assertThat(sample).hasSize(4 * 5);
        for (int k = 0; k < 5; k++) {
            assertThat(Arrays.copyOfRange(sample, 4 * k, 4 * k + 4)).as("object %d", 2 * k)
                    .containsExactly(footprintOf(spheres.get(2 * k)));
        }
        assertThat(Arrays.copyOfRange(sample, 0, 4)).as("the first sphere is in view")
                .satisfies(f -> assertThat(f[0]).isLessThanOrEqualTo(f[2]));
        assertThat(Arrays.copyOfRange(sample, 16, 20)).as("the ninth sphere, at x = 8, is beside the view")
                .satisfies(f -> assertThat(f[0]).isGreaterThan(f[2]));
    }

    @Test
    void holdsEveryObjectWhenThereAreFewerThanTheMost() {
        List<IGeometry> spheres = row(3);

        int[] sample = FOOTPRINT.ofSample(spheres, 4096);

        assertThat(sample).containsExactly(concat(footprintOf(spheres.get(0)), footprintOf(spheres.get(1)),
                footprintOf(spheres.get(2))));
    }

    @Test
    void theNarrowerRoundingFromTheEyeIsTakenForACamerasRaysOfOrdinaryLengthsOnly() {
        Vector3f eye = new Vector3f(0, 0, 10);
        Vector3f down = new Vector3f(0, 0, -1);

        assertThat(perspective(new PerspectiveCamera(eye, down, 60), 1920, 1080).raysInRange()).as("60°").isTrue();
        assertThat(perspective(new PerspectiveCamera(eye, down, 179.99f), 1920, 1080).raysInRange()).as("179.99°").isTrue();
        // f = 50 / tan(0.95e-17°) ≈ 3e20: a direction's |R|₁ beyond 1e20, where the triangle test's floats may overflow
        assertThat(perspective(new PerspectiveCamera(eye, down, 1.9e-17f), 100, 60).raysInRange()).as("1.9e-17°").isFalse();
    }

    private static PerspectiveFootprint perspective(PerspectiveCamera camera, int width, int height) {
        return (PerspectiveFootprint) ImageFootprint.of(camera, width, height, 0);
    }

    private static int[] concat(int[]... parts) {
        return Arrays.stream(parts).flatMapToInt(Arrays::stream).toArray();
    }
}
