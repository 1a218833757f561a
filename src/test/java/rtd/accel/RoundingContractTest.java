package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.BoundingBox;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.geometry.Triangle;
import rtd.geometry.Sphere;
import rtd.geometry.Box;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.MixedScenes;

/**
 * The engine's margins hold for every shape: a hit its float test reports at t lies in its box
 * ({@link rtd.geometry.IGeometry#bounds}) grown by its {@link KnownShapes#rounding} at the distance {@code t·|R|}, for rays from near
 * and far, where rounding makes the tests report hits beside the true surface.
 */
@DisplayName("Each shape's box holds every hit its test reports")
class RoundingContractTest {

    @ParameterizedTest(name = "random objects {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void evenForRaysFromFarAway(long seed) {
        Scene scene = MixedScenes.generate(seed, 300);
        Random random = new Random(seed);
        int hits = 0;
        for (int r = 0; r < 100_000; r++) {
            Ray ray = MixedScenes.ray(random, scene);
            IGeometry object = scene.objects().get(random.nextInt(scene.objects().size()));
            Intersection hit = object.intersect(ray);
            BoundingBox box = object.bounds();
            if (!hit.happened() || !box.isBounded()) {
                continue;
            }
            hits++;
            double distance = hit.t() * (double) ray.direction().magnitude();
            Rounding rounding = KnownShapes.rounding(object);
            double grow = rounding.linear() * distance
                    + Math.min(KnownShapes.ROUNDING_CONE * distance, rounding.quadratic() * distance * distance);
            Vector3f o = ray.origin();
            Vector3f d = ray.direction();
            double[] p = {o.x() + (double) d.x() * hit.t(), o.y() + (double) d.y() * hit.t(), o.z() + (double) d.z() * hit.t()};
            double[] min = {box.min().x(), box.min().y(), box.min().z()};
            double[] max = {box.max().x(), box.max().y(), box.max().z()};
            for (int k = 0; k < 3; k++) {
                assertThat(p[k]).as("ray %d %s, %s, axis %d", r, ray, object.kind(), k)
                        .isBetween(min[k] - grow, max[k] + grow);
            }
        }
        assertThat(hits).as("hits").isGreaterThan(1_000);
    }

    /**
     * Rays from one point (a perspective camera's eye) at triangles far from the origin, seen
     * steeply and flat, from near and far, aimed at their edges and just beside them: each hit
     * lies in the box grown by {@link KnownShapes#roundingFrom} that point, which is far less than
     * {@link IGeometry#rounding} where the rays meet the plane steeply.
     */
    @ParameterizedTest(name = "random triangles {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void andATrianglesHitsFromOnePointLieInItsBoxGrownByItsRoundingFromThatPoint(long seed) {
        Random random = new Random(seed);
        int hits = 0;
        int tighter = 0;
        for (int k = 0; k < 400; k++) {
            float size = (float) Math.pow(10, random.nextInt(4) - 1); // 0.1 to 100
            Vector3f centre = new Vector3f((float) (random.nextGaussian() * 1e4), (float) (random.nextGaussian() * 1e3),
                    (float) (random.nextGaussian() * 1e4));
            Vector3f p1 = centre.add(randomVector(random, size));
            Vector3f p2 = centre.add(randomVector(random, size));
            Vector3f p3 = random.nextInt(4) == 0 ? p1.add(p2.subtract(p1).multiply(0.5f)).add(randomVector(random, size / 50))
                    : centre.add(randomVector(random, size)); // a needle now and then
            Triangle triangle = new Triangle(p1, p2, p3, new Color(255, 255, 255), Material.DEFAULT);
            Vector3f n = triangle.planeNormal().normalize();
            // the point: 1 to 10,000 sizes away, from steeply above to nearly in the plane
            Vector3f along = randomVector(random, 1).subtract(n.multiply(randomVector(random, 1).dot(n))).normalize();
            float lift = (float) Math.pow(10, -3 * random.nextDouble()); // 1 down to 0.001
            float distance = size * (float) Math.pow(10, 4 * random.nextDouble());
            Vector3f origin = centre.add(n.multiply(lift).add(along.multiply(1 - lift)).normalize().multiply(distance));
            float[] box = new float[6];
            KnownShapes.putBox(triangle, box, 0);
            Rounding rounding = KnownShapes.roundingFrom(triangle, origin, box, 0);
            assertThat(rounding.linear()).isLessThanOrEqualTo(KnownShapes.rounding(triangle).linear());
            if (rounding.linear() < KnownShapes.rounding(triangle).linear() / 4) {
                tighter++;
            }
            for (int r = 0; r < 500; r++) {
                float a = (float) (random.nextDouble() * 1.2 - 0.1);
                float b = (float) (random.nextDouble() * (1.1 - a) - 0.05);
                Vector3f target = p1.add(p2.subtract(p1).multiply(a)).add(p3.subtract(p1).multiply(b));
                Vector3f direction = target.subtract(origin).multiply((float) Math.pow(10, 2 * random.nextDouble() - 1));
                Intersection hit = triangle.intersect(new Ray(origin, direction));
                if (hit.happened()) {
                    hits++;
                    assertInGrownBox(origin, direction, hit.t(), box, rounding, k, r);
                }
            }
        }
        assertThat(hits).as("hits").isGreaterThan(50_000);
        assertThat(tighter).as("triangles seen steeply enough to round four times less").isGreaterThan(100);
    }

    /**
     * A triangle whose normal is a subnormal number (sides of 6.5e-23: n = 4.2e-45): its test's
     * float ratio loses its digits, and it rounds as it may for any ray. (A review found the hit
     * of this ray 7.8e-5 beyond the narrower rounding, before the normal's size was checked.)
     */
    @Test
    void aTriangleOfASubnormalNormalRoundsFromOnePointAsFromAnywhere() {
        float a = 6.4837456E-23f; // a² = 3 · Float.MIN_VALUE
        Triangle tiny = new Triangle(new Vector3f(0, 0, 0), new Vector3f(a, 0, 0), new Vector3f(0, a, 0),
                new Color(255, 255, 255), Material.DEFAULT);
        Vector3f origin = new Vector3f(-14.7474f, -14.75f, 0.49f);
        Vector3f direction = new Vector3f(14.75f, 14.75f, -0.49f);
        float[] box = new float[6];
        KnownShapes.putBox(tiny, box, 0);
        Rounding rounding = KnownShapes.roundingFrom(tiny, origin, box, 0);
        Intersection hit = tiny.intersect(new Ray(origin, direction));

        assertThat(rounding).isEqualTo(KnownShapes.rounding(tiny));
        assertThat(hit.happened()).isTrue();
        assertInGrownBox(origin, direction, hit.t(), box, rounding, 0, 0);
    }

    private static Vector3f randomVector(Random random, float size) {
        return new Vector3f((float) random.nextGaussian() * size, (float) random.nextGaussian() * size,
                (float) random.nextGaussian() * size);
    }

    private static void assertInGrownBox(Vector3f o, Vector3f d, float t, float[] box, Rounding rounding, int k, int r) {
        double distance = t * Math.sqrt((double) d.x() * d.x() + (double) d.y() * d.y() + (double) d.z() * d.z());
        double grow = rounding.linear() * distance;
        double[] p = {o.x() + (double) d.x() * t, o.y() + (double) d.y() * t, o.z() + (double) d.z() * t};
        for (int axis = 0; axis < 3; axis++) {
            assertThat(p[axis]).as("triangle %d, ray %d, axis %d", k, r, axis)
                    .isBetween(box[axis] - grow, box[axis + 3] + grow);
        }
    }
}
