package rtd.camera;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import rtd.math.Ray;
import rtd.math.Vector3f;

/** {@link ICamera#putRay} writes exactly the numbers of {@link ICamera#generateRay}, to the bit. */
class PutRayTest {

    @Test
    void eachCameraWritesGenerateRaysNumbersToTheBitAtWholeAndFractionalPoints() {
        SplittableRandom random = new SplittableRandom(7);
        for (int c = 0; c < 200; c++) {
            Vector3f position = randomVector(random, 1000);
            Vector3f direction = randomVector(random, 1);
            if (direction.magnitude() < 1e-3f) {
                continue;
            }
            List<ICamera> cameras = List.of(
                    new OrthographicCamera(position, direction, (float) random.nextDouble(0.01, 500)),
                    new PerspectiveCamera(position, direction, (float) random.nextDouble(1, 179)));
            int w = random.nextInt(1, 4000);
            int h = random.nextInt(1, 4000);
            for (ICamera camera : cameras) {
                for (int k = 0; k < 50; k++) {
                    float x = k % 2 == 0 ? random.nextInt(w) : (float) random.nextDouble(0, w);
                    float y = k % 2 == 0 ? random.nextInt(h) : (float) random.nextDouble(0, h);
                    assertThat(put(camera, x, y, w, h)).containsExactly(numbers(camera.generateRay(x, y, w, h)));
                }
            }
        }
    }

    @Test
    void writesSixNumbersWhereItIsToldAndNothingElse() {
        ICamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50);
        float[] into = new float[10];
        java.util.Arrays.fill(into, -7f);

        camera.putRay(3, 4, 16, 9, into, 2);

        assertThat(into).containsExactly(-7f, -7f, -0.1f, 0f, 20f, 0f, 0f, -1f, -7f, -7f);
    }

    private static float[] put(ICamera camera, float x, float y, int w, int h) {
        float[] into = new float[6];
        camera.putRay(x, y, w, h, into, 0);
        return into;
    }

    /** The numbers' bits compared as floats: containsExactly uses equals, which tells -0 from 0 and NaN from NaN alike. */
    private static float[] numbers(Ray ray) {
        return new float[] {ray.origin().x(), ray.origin().y(), ray.origin().z(),
            ray.direction().x(), ray.direction().y(), ray.direction().z()};
    }

    private static Vector3f randomVector(SplittableRandom random, double scale) {
        return new Vector3f((float) random.nextDouble(-scale, scale), (float) random.nextDouble(-scale, scale),
                (float) random.nextDouble(-scale, scale));
    }
}
