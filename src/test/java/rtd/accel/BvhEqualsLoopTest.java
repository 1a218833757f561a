package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;
import static rtd.accel.SameHit.assertSame;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.scene.Scene;
import rtd.testing.MixedScenes;

/**
 * The hierarchy's answer to "what does this ray hit?" is the paper's loop's, for any ray: from
 * inside, around and far outside random scenes of every kind of object, one at a time, in
 * bundles of unrelated rays, in beams of parallel rays and in beams of rays from one point.
 */
@DisplayName("The BVH finds the loop's hit")
class BvhEqualsLoopTest {


    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10})
    void forRandomRaysFromAnywhere(long seed) {
        Scene scene = MixedScenes.generate(seed, 50 + (int) (seed * 97 % 400));
        BvhTracer tracer = Bvh.build(scene).newTracer();
        Random random = new Random(seed);
        int hits = 0;
        for (int r = 0; r < 20_000; r++) {
            Ray ray = MixedScenes.ray(random, scene);
            Hit expected = scene.nearestHit(ray);
            assertSame(tracer.nearestHit(ray), expected, "ray " + r + " " + ray);
            hits += expected == null ? 0 : 1;
        }
        assertThat(hits).as("rays that hit something").isGreaterThan(2_000);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {21, 22, 23, 24})
    void forBundlesOfUnrelatedRaysOfParallelRaysAndOfRaysFromOnePoint(long seed) {
        Scene scene = MixedScenes.generate(seed, 300);
        BvhTracer tracer = Bvh.build(scene).newTracer();
        Random random = new Random(seed);
        HitBuffer hits = new HitBuffer(64);
        for (int b = 0; b < 450; b++) {
            Ray[] rays = new Ray[64];
            Ray first = MixedScenes.ray(random, scene);
            float spacing = (float) Math.pow(10, random.nextInt(5) - 3);
            float fan = (float) Math.pow(10, -1 - random.nextInt(6)) * first.direction().magnitude();
            for (int i = 0; i < rays.length; i++) {
                rays[i] = switch (b % 3) {
                    case 0 -> new Ray(first.origin().add(new Vector3f(i % 8 * spacing, i / 8 * spacing, 0)), first.direction());
                    case 1 -> new Ray(first.origin(), first.direction().add(new Vector3f(i % 8 * fan, i / 8 * fan, (i % 3) * fan)));
                    default -> MixedScenes.ray(random, scene);
                };
            }
            RayBundle bundle = new RayBundle(64);
            bundle.fill(rays);
            tracer.traceAll(bundle, hits);
            for (int i = 0; i < rays.length; i++) {
                Hit expected = scene.nearestHit(rays[i]);
                assertSame(hits.hit(i, bundle, scene.objects()), expected, "bundle " + b + " ray " + i);
            }
        }
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {31, 32, 33, 34})
    void forShadowRaysThatAskOnlyWhetherAnythingIsNearerThanTheLight(long seed) {
        Scene scene = MixedScenes.generate(seed, 50 + (int) (seed * 53 % 300));
        BvhTracer tracer = Bvh.build(scene).newTracer();
        Random random = new Random(seed);
        int blocked = 0;
        for (int r = 0; r < 20_000; r++) {
            Ray ray = MixedScenes.ray(random, scene);
            Hit nearest = scene.nearestHit(ray);
            float limit = nearest == null || random.nextInt(4) == 0
                    ? (float) Math.pow(10, random.nextInt(8) - 2)
                    : switch (random.nextInt(3)) {
                        case 0 -> nearest.distance(); // a light exactly at the hit: not nearer, so not blocked
                        case 1 -> Math.nextUp(nearest.distance());
                        default -> nearest.distance() * (0.5f + random.nextFloat());
                    };
            boolean expected = nearest != null && nearest.distance() < limit;
            assertThat(tracer.blocked(ray, limit)).as("ray %d %s, limit %s", r, ray, limit).isEqualTo(expected);
            blocked += expected ? 1 : 0;
        }
        assertThat(blocked).as("rays blocked").isGreaterThan(2_000).isLessThan(18_000);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {41, 42, 43})
    void forShadowRaysFromNeighbouringPointsWhichTheSameObjectsMostlyBlock(long seed) {
        // Rays from points close together towards two lights in turn: the objects that blocked
        // the last rays, tried first, block most of them; the answer must stay the loop's even
        // where such an object lies beyond the light, or exactly at it.
        Scene scene = MixedScenes.generate(seed, 300);
        BvhTracer tracer = Bvh.build(scene).newTracer();
        Random random = new Random(seed);
        Vector3f[] lights = {new Vector3f(0, 40, 0), new Vector3f(35, 5, -20)};
        int blocked = 0;
        for (int patch = 0; patch < 200; patch++) {
            Vector3f centre = new Vector3f(random.nextFloat() * 20 - 10, -12, random.nextFloat() * 20 - 10);
            for (int r = 0; r < 100; r++) {
                Vector3f from = centre.add(new Vector3f(random.nextFloat() * 0.2f, 0, random.nextFloat() * 0.2f));
                Ray ray = new Ray(from, lights[r % 2].subtract(from));
                Hit nearest = scene.nearestHit(ray);
                float limit = nearest == null ? ray.direction().magnitude() : switch (random.nextInt(3)) {
                    case 0 -> nearest.distance(); // a light exactly at the hit: not nearer, so not blocked
                    case 1 -> nearest.distance() * 0.99f;
                    default -> ray.direction().magnitude();
                };
                boolean expected = nearest != null && nearest.distance() < limit;
                assertThat(tracer.blocked(ray, limit)).as("patch %d ray %d %s, limit %s", patch, r, ray, limit)
                        .isEqualTo(expected);
                blocked += expected ? 1 : 0;
            }
        }
        assertThat(blocked).as("rays blocked").isGreaterThan(1_000);
    }
}
