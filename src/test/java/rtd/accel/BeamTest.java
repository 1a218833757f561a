package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.Beam;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.geometry.Sphere;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.ParallelRenderer;
import rtd.render.RayBundle;
import rtd.render.RenderProgress;
import rtd.scene.Scene;
import rtd.testing.RandomScenes;
import rtd.testing.Scenes;

@DisplayName("Bundles of rays and packed spheres")
class BeamTest {

    /** The rays of an 8 × 8 square of pixels with its top left corner at (left, top). */
    static RayBundle square(ICamera camera, int left, int top, int width, int height) {
        RayBundle rays = new RayBundle(64);
        rays.fill(camera, left, top, left + 8, top + 8, width, height);
        return rays;
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void aBundleOfParallelRaysSeesWhatEachRaySeesAlone(long seed) {
        Scene scene = RandomScenes.generate(seed, 3_000);
        Bvh bvh = Bvh.build(scene);
        BvhTracer bundled = bvh.newTracer();
        BvhTracer alone = bvh.newTracer();
        int[] rgb = new int[64];
        for (int top = 0; top < 120; top += 8) {
            for (int left = 0; left < 160; left += 8) {
                RayBundle rays = square(scene.camera(), left, top, 160, 120);
                bundled.traceAll(rays, rgb);
                for (int i = 0; i < rays.count(); i++) {
                    assertThat(rgb[i]).as("ray %d of the square at (%d, %d)", i, left, top)
                            .isEqualTo(alone.trace(rays.ray(i)).getRGB());
                }
            }
        }
        assertThat(bundled.work().intersectionTests()).isLessThanOrEqualTo(3 * alone.work().intersectionTests());
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {11, 12})
    void raysOfDifferentDirectionsAreTracedOneByOne(long seed) {
        Scene scene = RandomScenes.generate(seed, 500);
        BvhTracer tracer = Bvh.build(scene).newTracer();
        RayBundle square = square(scene.camera(), 40, 30, 80, 60);
        square.make();
        Ray[] chosen = new Ray[square.count()];
        for (int i = 0; i < chosen.length; i++) {
            chosen[i] = square.ray(i);
        }
        chosen[5] = new Ray(chosen[5].origin(), chosen[5].direction().multiply(2)); // same line, other direction vector
        RayBundle rays = new RayBundle(64);
        rays.fill(chosen);
        assertThat(square.beam()).isNotNull();
        assertThat(rays.beam()).isNull();
        int[] rgb = new int[64];
        tracer.traceAll(rays, rgb);
        for (int i = 0; i < rays.count(); i++) {
            assertThat(rgb[i]).isEqualTo(scene.trace(rays.ray(i)).getRGB());
        }
    }

    /** The orthographic camera, counting the rays it makes; with or without its beams. */
    private static final class CountingCamera implements ICamera {
        private final ICamera camera;
        private final boolean offersBeams;
        private final AtomicLong raysMade = new AtomicLong();

        CountingCamera(ICamera camera, boolean offersBeams) {
            this.camera = camera;
            this.offersBeams = offersBeams;
        }

        @Override
        public Ray generateRay(int x, int y, int w, int h) {
            raysMade.incrementAndGet();
            return camera.generateRay(x, y, w, h);
        }

        @Override
        public Beam beam(int left, int top, int right, int bottom, int w, int h) {
            return offersBeams ? camera.beam(left, top, right, bottom, w, h) : null;
        }

        @Override
        public Vector3f position() {
            return camera.position();
        }

        @Override
        public float farthestOrigin(Vector3f point, float reach) {
            return camera.farthestOrigin(point, reach);
        }
    }

    private static int[] render(Scene scene, ICamera camera, int width, int height) {
        Scene seenBy = new Scene(scene.ambient(), camera, scene.objects());
        return ParallelRenderer.render(camera, Bvh.build(seenBy)::newTracer, width, height, 2, new RenderProgress())
                .image().rgb();
    }

    @Test
    void squaresThatReachNoObjectArePaintedWithTheBackgroundWithoutMakingTheirRays() {
        Scene scene = Scenes.example("input_rtd");
        CountingCamera camera = new CountingCamera(scene.camera(), true);
        int[] pixels = render(scene, camera, 480, 270);
        assertThat(pixels).isEqualTo(render(scene, new CountingCamera(scene.camera(), false), 480, 270));
        long background = Arrays.stream(pixels).filter(rgb -> rgb == scene.ambient().getRGB()).count();
        assertThat(background).as("background pixels").isGreaterThan(480 * 270 / 2);
        // Each square costs its 4 corners; only squares near a sphere make all their rays.
        assertThat(camera.raysMade.get()).as("rays made").isLessThan(480 * 270 - background / 2);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {31, 32, 33})
    void aCameraThatOffersNoBeamGivesThePapersPixelsThroughTheBvh(long seed) {
        Scene scene = RandomScenes.generate(seed, 300);
        CountingCamera camera = new CountingCamera(scene.camera(), false);
        int[] pixels = render(scene, camera, 120, 90);
        assertThat(pixels).isEqualTo(render(scene, scene.camera(), 120, 90));
        assertThat(camera.raysMade.get()).as("rays made").isEqualTo(120 * 90);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22, 23})
    void packedSpheresFindTheSameHitToTheLastBitAsTheSphere(long seed) {
        Random random = new Random(seed);
        IGeometry[] spheres = new IGeometry[200];
        for (int i = 0; i < spheres.length; i++) {
            spheres[i] = new Sphere(new Vector3f(random.nextFloat() * 20 - 10, random.nextFloat() * 20 - 10,
                    random.nextFloat() * 20 - 10), random.nextFloat() * 5, null);
        }
        PackedSpheres packed = PackedSpheres.packOrNull(spheres, false);
        PackedSpheres packedInParallel = PackedSpheres.packOrNull(spheres, true);
        int hits = 0;
        for (int r = 0; r < 2_000; r++) {
            int i = r % spheres.length;
            Sphere aim = (Sphere) spheres[i];
            float spread = 3 * aim.radius();
            Vector3f origin = aim.center().add(new Vector3f((random.nextFloat() - 0.5f) * spread,
                    (random.nextFloat() - 0.5f) * spread, r % 7 == 0 ? 0 : 30)); // some start inside
            Vector3f direction = new Vector3f((random.nextFloat() - 0.5f) * 0.1f, (random.nextFloat() - 0.5f) * 0.1f,
                    -1 - random.nextFloat());
            Ray ray = new Ray(origin, direction);
            Intersection expected = spheres[i].intersect(ray);
            float t = packed.hit(i, origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z(),
                    direction.dot(direction));
            assertThat(Float.floatToIntBits(t)).isEqualTo(Float.floatToIntBits(expected.t()));
            assertThat(Float.floatToIntBits(packedInParallel.hit(i, origin.x(), origin.y(), origin.z(), direction.x(),
                    direction.y(), direction.z(), direction.dot(direction)))).isEqualTo(Float.floatToIntBits(t));
            if (expected.happened()) {
                hits++;
                float distance = PackedSpheres.distance(t, origin.x(), origin.y(), origin.z(),
                        direction.x(), direction.y(), direction.z());
                assertThat(distance).isEqualTo(expected.contactCoord().subtract(origin).magnitude());
            }
        }
        assertThat(hits).as("rays that hit").isGreaterThan(500).isLessThan(2_000);
    }
}
