package rtd.explain;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
import rtd.scene.Scene;
import rtd.testing.MixedScenes;

@DisplayName("The explained intersection tests")
class ShapeStepsTest {

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void findTheSameTToTheLastBitAsEachShapesOwnTestForRaysFromAnywhere(long seed) {
        Scene scene = MixedScenes.generate(seed, 30);
        Random random = new Random(seed);
        for (int k = 0; k < 300; k++) {
            Ray ray = MixedScenes.ray(random, scene);
            for (IGeometry object : scene.objects()) {
                float own = object.intersect(ray).t();
                float explained = IntersectionSteps.explain(new Text(), "", object, ray);
                assertThat(explained >= 0 ? Float.floatToIntBits(explained) : -1)
                        .as("%s and %s", object, ray).isEqualTo(own >= 0 ? Float.floatToIntBits(own) : -1);
            }
        }
    }
}
