package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.scene.Scene;
import rtd.testing.Scenes;

@DisplayName("The beam of a square of pixels")
class BeamOfSquareTest {

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void theOrthographicCamerasFourCornersBoundEveryOriginOfTheSquareToTheLastBit(long seed) {
        Random random = new Random(seed);
        Beam beam = new Beam();
        RayBundle bundle = new RayBundle(256);
        for (int c = 0; c < 40; c++) {
            OrthographicCamera camera = randomCamera(random);
            int width = 1 + random.nextInt(3000);
            int height = 1 + random.nextInt(3000);
            for (int s = 0; s < 20; s++) {
                int left = random.nextInt(width);
                int top = random.nextInt(height);
                int right = Math.min(width, left + 1 + random.nextInt(16));
                int bottom = Math.min(height, top + 1 + random.nextInt(16));
                bundle.fill(camera, left, top, right, bottom, width, height);
                assertThat(beam.aimAt(bundle)).isTrue();
                for (int i = 0; i < bundle.count(); i++) {
                    Ray ray = bundle.ray(i);
                    assertInside(ray.origin(), beam);
                    assertThat(ray.direction()).isEqualTo(new Vector3f(beam.dx, beam.dy, beam.dz));
                }
            }
        }
    }

    @Test
    void originsTooFarOutForFloatGiveNoBeam() {
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 1e-38f);
        RayBundle bundle = new RayBundle(64);
        bundle.fill(camera, 0, 0, 8, 8, 1920, 1080);
        assertThat(bundle.ray(0).origin().isFinite()).isFalse();
        assertThat(new Beam().aimAt(bundle)).isFalse();
    }

    @Test
    void squaresThatReachNoObjectAreLeftWithoutMakingTheirRays() {
        Scene scene = Scenes.example("input_rtd");
        BvhTracer tracer = Bvh.build(scene).newTracer();
        RayBundle bundle = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        int squares = 0;
        int made = 0;
        for (int top = 0; top < 1080; top += 8) {
            for (int left = 0; left < 1920; left += 8) {
                bundle.fill(scene.camera(), left, top, left + 8, top + 8, 1920, 1080);
                tracer.traceAll(bundle, hits);
                squares++;
                made += bundle.isMade() ? 1 : 0;
                for (int i = 0; i < bundle.count(); i++) {
                    assertThat(hits.index(i)).isEqualTo(indexOf(scene.nearestHit(bundle.ray(i))));
                }
            }
        }
        assertThat(made).as("squares whose rays were made, of " + squares).isPositive().isLessThan(squares / 2);
    }

    private static int indexOf(Hit hit) {
        return hit == null ? -1 : hit.index();
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
        assertThat(origin.x()).isBetween(beam.lowest[0], beam.highest[0]);
        assertThat(origin.y()).isBetween(beam.lowest[1], beam.highest[1]);
        assertThat(origin.z()).isBetween(beam.lowest[2], beam.highest[2]);
    }
}
