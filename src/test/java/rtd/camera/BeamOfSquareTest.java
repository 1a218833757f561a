package rtd.camera;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The beam of a square of pixels of the orthographic camera")
class BeamOfSquareTest {

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void theFourCornersBoundEveryOriginOfTheSquareToTheLastBit(long seed) {
        Random random = new Random(seed);
        for (int c = 0; c < 40; c++) {
            OrthographicCamera camera = randomCamera(random);
            int width = 1 + random.nextInt(3000);
            int height = 1 + random.nextInt(3000);
            for (int s = 0; s < 20; s++) {
                int left = random.nextInt(width);
                int top = random.nextInt(height);
                int right = Math.min(width, left + 1 + random.nextInt(16));
                int bottom = Math.min(height, top + 1 + random.nextInt(16));
                Beam beam = camera.beam(left, top, right, bottom, width, height);
                assertThat(beam).isNotNull();
                assertThat(beam.direction()).isEqualTo(camera.direction());
                for (int y = top; y < bottom; y++) {
                    for (int x = left; x < right; x++) {
                        Ray ray = camera.generateRay(x, y, width, height);
                        assertInside(ray.origin(), beam);
                        assertThat(ray.direction()).isEqualTo(beam.direction());
                    }
                }
            }
        }
    }

    @Test
    void aSingleRowOrColumnOrPixelIsABeamToo() {
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50);
        Beam pixel = camera.beam(7, 9, 8, 10, 1920, 1080);
        assertThat(pixel.lowestOrigin()).isEqualTo(camera.generateRay(7, 9, 1920, 1080).origin());
        assertThat(pixel.highestOrigin()).isEqualTo(pixel.lowestOrigin());
        Beam row = camera.beam(0, 0, 1920, 1, 1920, 1080);
        assertThat(row.lowestOrigin().x()).isEqualTo(-960 / 50f);
        assertThat(row.highestOrigin().x()).isEqualTo(959 / 50f);
    }

    @Test
    void originsTooFarOutForFloatGiveNoBeam() {
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 1e-38f);
        assertThat(camera.generateRay(0, 0, 1920, 1080).origin().isFinite()).isFalse();
        assertThat(camera.beam(0, 0, 8, 8, 1920, 1080)).isNull();
    }

    private static OrthographicCamera randomCamera(Random random) {
        float scale = (float) Math.pow(10, random.nextInt(7) - 3);
        Vector3f position = new Vector3f(coordinate(random, scale), coordinate(random, scale), coordinate(random, scale));
        Vector3f direction = random.nextInt(8) == 0
                ? new Vector3f(0, random.nextBoolean() ? 1 : -1, 0) // straight up or down
                : new Vector3f(coordinate(random, 1), coordinate(random, 1), coordinate(random, 1));
        if (direction.magnitude() == 0) {
            direction = new Vector3f(0, 0, -1);
        }
        return new OrthographicCamera(position, direction, (float) Math.pow(10, random.nextInt(6) - 2) * (1 + random.nextFloat()));
    }

    private static float coordinate(Random random, float scale) {
        return (random.nextFloat() * 2 - 1) * scale;
    }

    private static void assertInside(Vector3f origin, Beam beam) {
        assertThat(origin.x()).isBetween(beam.lowestOrigin().x(), beam.highestOrigin().x());
        assertThat(origin.y()).isBetween(beam.lowestOrigin().y(), beam.highestOrigin().y());
        assertThat(origin.z()).isBetween(beam.lowestOrigin().z(), beam.highestOrigin().z());
    }
}
