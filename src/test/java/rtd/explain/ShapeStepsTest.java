package rtd.explain;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
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

    /**
     * Rays at the edge of float, which random rays never are: one so nearly parallel to a plane
     * that its t overflows to ∞, directions so short that a box's t does, and rays through a
     * triangle's edge and corner and past a sphere's rim.
     */
    @Test
    void agreeWithEachShapesOwnTestForRaysAtTheEdgeOfFloat() {
        Material m = Material.DEFAULT;
        Color c = new Color(9, 9, 9);
        List<IGeometry> shapes = List.of(new Plane(new Vector3f(0, -1, 0), new Vector3f(0, 1, 0), c, m),
                Box.between(new Vector3f(1, 1, 1), new Vector3f(2, 2, 2), c, m),
                new Triangle(new Vector3f(0, 0, 5), new Vector3f(1, 0, 5), new Vector3f(0, 1, 5), c, m),
                new Sphere(new Vector3f(0, 0, 5), 1, c, m));
        List<Ray> rays = List.of(new Ray(new Vector3f(0, 1, 0), new Vector3f(1, -1e-45f, 0)),
                new Ray(Vector3f.ZERO, new Vector3f(1e-40f, 1e-40f, 1e-40f)),
                new Ray(new Vector3f(1.5f, 1.5f, -3), new Vector3f(0, 0, 1e-42f)),
                new Ray(new Vector3f(0.5f, 0, 0), new Vector3f(0, 0, 1)), new Ray(Vector3f.ZERO, new Vector3f(0, 0, 1)),
                new Ray(new Vector3f(1, 0, 0), new Vector3f(0, 0, 1)), new Ray(new Vector3f(0, 1, 0), new Vector3f(0, 0, 1)));
        for (IGeometry shape : shapes) {
            for (Ray ray : rays) {
                float own = shape.intersect(ray).t();
                float explained = IntersectionSteps.explain(new Text(), "", shape, ray);
                assertThat(explained >= 0 ? Float.floatToIntBits(explained) : -1)
                        .as("%s and %s", shape, ray).isEqualTo(own >= 0 ? Float.floatToIntBits(own) : -1);
            }
        }
    }

    /**
     * The box from (0|−1|−1) to (2|1|0), a ray from (1|0|10) along (0|0|−1): along z it is between
     * the faces from t = (0 − 10)/−1 = 10 (the max face, met first) to (−1 − 10)/−1 = 11, listed
     * near to far.
     */
    @Test
    void aBoxsSlabsAreListedNearToFar() {
        Box box = Box.between(new Vector3f(0, -1, -1), new Vector3f(2, 1, 0), new Color(1, 2, 3), Material.DEFAULT);
        Text text = new Text();
        float t = IntersectionSteps.explain(text, "", box, new Ray(new Vector3f(1, 0, 10), new Vector3f(0, 0, -1)));
        assertThat(t).isEqualTo(10f);
        assertThat(text.toString()).contains("z: t from (max − O)/R = 10 to (min − O)/R = 11")
                .contains("x: Rx = 0, the ray runs parallel to the slab and is inside it everywhere")
                .contains("t = enter = 10: a hit");
    }
}
