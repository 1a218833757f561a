package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.geometry.Material;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.scene.Scene;
import rtd.testing.RandomScenes;

/** Squares of parallel rays traced together, and the packed leaf tests, against rays one at a time. */
@DisplayName("Rays traced together")
class BeamTest {

    static RayBundle square(ICamera camera, int left, int top, int width, int height) {
        RayBundle rays = new RayBundle(64);
        rays.fill(camera, left, top, left + 8, top + 8, width, height);
        return rays;
    }

    /** Asserts that entry i of {@code hits} is {@code expected}, to the last bit. */
    static void assertSameHit(HitBuffer hits, int i, Hit expected, String what) {
        if (expected == null) {
            assertThat(hits.index(i)).as(what).isEqualTo(-1);
            return;
        }
        assertThat(hits.index(i)).as(what).isEqualTo(expected.index());
        assertThat(Float.floatToIntBits(hits.t(i))).as(what + ": t").isEqualTo(Float.floatToIntBits(expected.t()));
        assertThat(hits.distance(i)).as(what + ": distance").isEqualTo(expected.distance());
    }

    /**
     * Whether ray {@code i} of the square at ({@code left}, {@code top}) is also checked against
     * the paper's loop: one ray in four, a different one in each square, so that every place in a
     * square is checked somewhere. Every ray is checked against the hierarchy's one-ray walk,
     * which {@link BvhEqualsLoopTest} holds to the loop for rays of every kind.
     */
    private static boolean sampled(int i, int left, int top) {
        return (i + left / 8 + top / 8) % 4 == 0;
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void aSquareOfParallelRaysFindsTheHitsEachRayFindsAlone(long seed) {
        Scene scene = RandomScenes.generate(seed, 3_000);
        Bvh bvh = Bvh.build(scene);
        BvhTracer bundled = bvh.newTracer();
        BvhTracer alone = bvh.newTracer();
        HitBuffer hits = new HitBuffer(64);
        for (int top = 0; top < 120; top += 8) {
            for (int left = 0; left < 160; left += 8) {
                RayBundle rays = square(scene.camera(), left, top, 160, 120);
                bundled.traceAll(rays, hits);
                for (int i = 0; i < rays.count(); i++) {
                    assertSameHit(hits, i, alone.nearestHit(rays.ray(i)),
                            "ray " + i + " of the square at (" + left + ", " + top + ")");
                    if (sampled(i, left, top)) {
                        assertSameHit(hits, i, scene.nearestHit(rays.ray(i)), "the paper's loop, ray " + i);
                    }
                }
            }
        }
        assertThat(bundled.work().intersectionTests()).isLessThanOrEqualTo(3 * alone.work().intersectionTests());
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void aSquareOfAPerspectiveCameraFindsTheHitsEachRayFindsAloneAndVisitsFewerBoxes(long seed) {
        Scene scene = RandomScenes.generate(seed, 3_000);
        OrthographicCamera paper = (OrthographicCamera) scene.camera();
        // from where the orthographic camera stands, or from the middle of the spheres
        Vector3f eye = seed % 2 == 0 ? paper.position() : new Vector3f(0.5f, 0.25f, -0.5f);
        ICamera camera = new PerspectiveCamera(eye, paper.direction(), 10 + 4 * seed); // squares of 0.4° to 0.9°: beams
        Bvh bvh = Bvh.build(scene);
        BvhTracer bundled = bvh.newTracer();
        BvhTracer alone = bvh.newTracer();
        HitBuffer hits = new HitBuffer(64);
        int hitCount = 0;
        for (int top = 0; top < 240; top += 8) {
            for (int left = 0; left < 320; left += 8) {
                RayBundle rays = square(camera, left, top, 320, 240);
                bundled.traceAll(rays, hits);
                for (int i = 0; i < rays.count(); i++) {
                    assertSameHit(hits, i, alone.nearestHit(rays.ray(i)),
                            "ray " + i + " of the square at (" + left + ", " + top + ")");
                    if (sampled(i, left, top)) {
                        assertSameHit(hits, i, scene.nearestHit(rays.ray(i)), "the paper's loop, ray " + i);
                    }
                    hitCount += hits.index(i) < 0 ? 0 : 1;
                }
            }
        }
        assertThat(hitCount).as("rays that hit").isGreaterThan(1_000);
        assertThat(bundled.work().nodesVisited()).isLessThan(alone.work().nodesVisited());
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {31, 32, 33, 34})
    void aRunOfSquaresWhoseHitPointsAreReadIsTracedAtOnceOnlyIfEveryOneOfItsRaysMisses(long seed) {
        Scene scene = RandomScenes.generate(seed, 12);
        BvhTracer tracer = Bvh.build(scene).newTracer();
        int width = 320;
        int height = 240;
        int atOnce = 0;
        int notAtOnce = 0;
        for (int top = 0; top < height; top += 8) {
            for (int left = 0; left < width; left += 64) {
                RayBundle run = new RayBundle(64 * 8);
                run.fill(scene.camera(), left, top, left + 64, top + 8, width, height);
                long raysBefore = tracer.work().rays();
                HitBuffer hits = new HitBuffer(64 * 8);
                if (!tracer.traceAtOnce(run, hits)) {
                    notAtOnce++;
                    assertThat(tracer.work().rays()).as("rays traced").isEqualTo(raysBefore);
                    continue;
                }
                atOnce++;
                assertThat(run.isMade()).as("the run's rays were made").isFalse();
                assertThat(tracer.work().rays()).as("rays traced").isEqualTo(raysBefore + run.count());
                assertThat(hits.missedAll()).as("every ray missed").isTrue();
                for (int i = 0; i < run.count(); i++) {
                    assertThat(scene.nearestHit(run.ray(i)))
                            .as("ray " + i + " of the run at (" + left + ", " + top + ")").isNull();
                }
            }
        }
        assertThat(atOnce).as("runs traced at once").isPositive();
        assertThat(notAtOnce).as("runs that reach an object").isPositive();
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {11, 12})
    void raysOfDifferentDirectionsAreTracedOneByOne(long seed) {
        Scene scene = RandomScenes.generate(seed, 500);
        BvhTracer tracer = Bvh.build(scene).newTracer();
        RayBundle square = square(scene.camera(), 40, 30, 80, 60);
        Ray[] chosen = new Ray[square.count()];
        for (int i = 0; i < chosen.length; i++) {
            chosen[i] = square.ray(i);
        }
        chosen[5] = new Ray(chosen[5].origin(), chosen[5].direction().multiply(2)); // same line, other direction vector
        RayBundle rays = new RayBundle(64);
        rays.fill(chosen);
        HitBuffer hits = new HitBuffer(64);
        tracer.traceAll(rays, hits);
        for (int i = 0; i < rays.count(); i++) {
            assertSameHit(hits, i, scene.nearestHit(rays.ray(i)), "ray " + i);
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22, 23})
    void packedSpheresAndTrianglesFindTheSameHitToTheLastBitAsTheirOwnTests(long seed) {
        Random random = new Random(seed);
        IGeometry[] objects = new IGeometry[200];
        for (int i = 0; i < objects.length; i++) {
            Vector3f centre = new Vector3f(random.nextFloat() * 20 - 10, random.nextFloat() * 20 - 10,
                    random.nextFloat() * 20 - 10);
            float size = random.nextFloat() * 5;
            objects[i] = i % 2 == 0 ? new Sphere(centre, size, Color.BLACK)
                    : new Triangle(centre.add(new Vector3f(-size, -size, 0)), centre.add(new Vector3f(size, -size, size)),
                            centre.add(new Vector3f(0, size, -size)), Color.BLACK, Material.DEFAULT);
        }
        Bvh bvh = Bvh.build(new Scene(Color.BLACK, RandomScenes.generate(1, 1).camera(), java.util.List.of(objects)));
        LeafObjects leaves = bvh.leaves;
        int hits = 0;
        for (int r = 0; r < 4_000; r++) {
            int i = r % objects.length;
            IGeometry object = objects[leaves.fileOrder[i]];
            Vector3f aim = object.bounds().centre();
            float spread = 3;
            Vector3f origin = aim.add(new Vector3f((random.nextFloat() - 0.5f) * spread,
                    (random.nextFloat() - 0.5f) * spread, r % 7 == 0 ? 0 : 30)); // some start inside
            Vector3f direction = new Vector3f((random.nextFloat() - 0.5f) * 0.1f, (random.nextFloat() - 0.5f) * 0.1f,
                    -1 - random.nextFloat());
            Intersection expected = object.intersect(new Ray(origin, direction));
            float t = leaves.t(i, origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z(),
                    direction.dot(direction));
            assertThat(Float.floatToIntBits(t)).isEqualTo(Float.floatToIntBits(expected.t()));
            if (expected.happened()) {
                hits++;
                float distance = LeafObjects.distance(t, origin.x(), origin.y(), origin.z(),
                        direction.x(), direction.y(), direction.z());
                assertThat(distance).isEqualTo(expected.contactCoord().subtract(origin).magnitude());
            }
        }
        assertThat(hits).as("rays that hit").isGreaterThan(500).isLessThan(4_000);
    }
}
