package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.geometry.Sphere;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.RandomScenes;

@DisplayName("Bundles of rays and packed spheres")
class BeamTest {

    /** The rays of an 8 × 8 square of pixels with its top left corner at (left, top). */
    static Ray[] square(ICamera camera, int left, int top, int width, int height) {
        Ray[] rays = new Ray[64];
        for (int i = 0; i < 64; i++) {
            rays[i] = camera.generateRay(left + i % 8, top + i / 8, width, height);
        }
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
                Ray[] rays = square(scene.camera(), left, top, 160, 120);
                bundled.traceAll(rays, rays.length, rgb);
                for (int i = 0; i < rays.length; i++) {
                    assertThat(rgb[i]).as("ray %d of the square at (%d, %d)", i, left, top)
                            .isEqualTo(alone.trace(rays[i]).getRGB());
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
        Ray[] rays = square(scene.camera(), 40, 30, 80, 60);
        rays[5] = new Ray(rays[5].origin(), rays[5].direction().multiply(2)); // same line, other direction vector
        assertThat(BeamLeaves.parallel(rays, rays.length)).isFalse();
        int[] rgb = new int[64];
        tracer.traceAll(rays, rays.length, rgb);
        for (int i = 0; i < rays.length; i++) {
            assertThat(rgb[i]).isEqualTo(scene.trace(rays[i]).getRGB());
        }
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
        PackedSpheres packed = PackedSpheres.packOrNull(spheres);
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
