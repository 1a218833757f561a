package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.MixedScenes;

/**
 * Every shape keeps the promise of {@link IGeometry#bounds}: a hit its float test reports at t
 * lies in its box grown by its {@link Rounding} at the distance {@code t·|R|}, for rays from near
 * and far, where rounding makes the tests report hits beside the true surface.
 */
@DisplayName("Each shape's box holds every hit its test reports")
class BoundsContractTest {

    @ParameterizedTest(name = "random objects {0}")
    @ValueSource(longs = {1, 2, 3})
    void andPutBoundsWritesTheNumbersOfThatBoxWithoutMakingIt(long seed) {
        // needles and tiny spheres among them, whose margins the numbers-only paths work out anew
        Scene scene = MixedScenes.generate(seed, 2_000);
        float[] written = new float[6];
        float[] made = new float[6];
        for (IGeometry object : scene.objects()) {
            object.putBounds(written, 0);
            object.bounds().put(made, 0);
            assertThat(written).as("%s", object).containsExactly(made);
        }
    }

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
            Rounding rounding = object.rounding();
            double grow = rounding.linear() * distance
                    + Math.min(IGeometry.ROUNDING_CONE * distance, rounding.quadratic() * distance * distance);
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
}
