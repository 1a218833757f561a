package rtd.shade;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.accel.Bvh;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.scene.AreaLight;
import rtd.scene.Light;
import rtd.scene.Scene;

/** Soft shadows: an area light lights as its samples do, each with its own shadow ray (Part III, "Area lights"). */
@DisplayName("Area lights")
class AreaLightShadingTest {

    private static final Color WHITE = new Color(255, 255, 255);
    /**
     * A line light from (−1|4|0) along u = (2|0|0) (v = 0), 2 × 1 samples: lights at C + ¼·u and
     * C + ¾·u, that is (−0.5|4|0) and (0.5|4|0), each of intensity ½.
     */
    private static final AreaLight LINE = new AreaLight(new Vector3f(-1, 4, 0), new Vector3f(2, 0, 0), Vector3f.ZERO, 2, 1,
            new Rgb(1, 1, 1));
    /** A white floor at y = 0, and a small box over it that stands between the origin and the sample at (0.5|4|0) only. */
    private static final Plane FLOOR = new Plane(Vector3f.ZERO, new Vector3f(0, 1, 0), WHITE, Material.DEFAULT);
    private static final Box BLOCKER = Box.between(new Vector3f(0.1f, 2, -0.2f), new Vector3f(0.5f, 2.2f, 0.2f), WHITE,
            Material.DEFAULT);
    private static final Ray DOWN_TO_THE_ORIGIN = new Ray(new Vector3f(0, 10, 0), new Vector3f(0, -1, 0));

    private static Scene scene(List<IGeometry> objects, List<Light> lights) {
        return new Scene(Color.BLACK, new OrthographicCamera(new Vector3f(0, 10, 0), new Vector3f(0, -1, 0), 10), objects,
                lights);
    }

    /** Counts the lights the shader finds lit and shadowed. */
    private static final class Counting implements ShadingObserver {
        int lit;
        int shadowed;

        @Override
        public void light(Light light, boolean inShadow, LightTerms terms) {
            if (inShadow) {
                shadowed++;
            } else {
                lit++;
            }
        }
    }

    @Test
    void itsSamplesLieAtTheCentresOfTheirCellsEachWithAShareOfTheLight() {
        assertThat(LINE.samples()).extracting(Light::position).containsExactly(new Vector3f(-0.5f, 4, 0),
                new Vector3f(0.5f, 4, 0));
        assertThat(LINE.samples()).extracting(Light::intensity).containsOnly(new Rgb(0.5f, 0.5f, 0.5f));
    }

    /**
     * The origin on the floor sees the sample at (−0.5|4|0) and not the one behind the box: one
     * of two samples lit. The lit one gives N·L = 4/√16.25 = 0.99228, diffuse 0.9·½·0.99228 =
     * 0.44653 and, seen from straight above, Rl·E = N·L, specular 0.9·½·0.99228^200 = 0.09547;
     * both give ambient 0.1·½: 0.1 + 0.44653 + 0.09547 = 0.64200, pixel 164.
     */
    @Test
    void aPointHalfInShadowGetsHalfTheSamples() {
        List<IGeometry> objects = List.of(FLOOR, BLOCKER);
        Scene scene = scene(objects, LINE.samples());
        Counting counting = new Counting();
        Rgb colour = new WhittedShader(scene, new LinearTracer(scene), counting).colourAt(DOWN_TO_THE_ORIGIN, 5);
        assertThat(counting.lit).as("samples lit").isEqualTo(1);
        assertThat(counting.shadowed).as("samples in shadow").isEqualTo(1);
        assertThat(colour.red()).isCloseTo(0.64200f, within(2e-4f));
        assertThat(colour.toColor()).isEqualTo(new Color(164, 164, 164));
    }

    /**
     * Without the box both samples light it: 0.1 + 2·(0.44653 + 0.09547) = 1.184 (white, once
     * clamped); with a second box, its mirror image, in the way of the other sample, ambient alone: 0.1.
     */
    @Test
    void aPointInFullLightOrFullShadowGetsAllOrNone() {
        Rgb open = colour(List.of(FLOOR), LINE.samples());
        assertThat(open.red()).isCloseTo(1.184f, within(2e-4f));
        Box mirrored = Box.between(new Vector3f(-0.5f, 2, -0.2f), new Vector3f(-0.1f, 2.2f, 0.2f), WHITE, Material.DEFAULT);
        assertThat(colour(List.of(FLOOR, BLOCKER, mirrored), LINE.samples()).red()).isCloseTo(0.1f, within(1e-6f));
    }

    /** The scene lit by the area light draws exactly as the one lit by its samples written as point lights, on the BVH too. */
    @Test
    void itLightsExactlyAsItsSamplesAsPointLights() {
        List<IGeometry> objects = List.of(FLOOR, BLOCKER);
        List<Light> points = new ArrayList<>();
        for (Light sample : LINE.samples()) {
            points.add(new Light(sample.position(), sample.intensity()));
        }
        Rgb area = colour(objects, LINE.samples());
        assertThat(colour(objects, points)).isEqualTo(area);
        Scene scene = scene(objects, LINE.samples());
        assertThat(new WhittedShader(scene, Bvh.build(scene).newTracer()).colourAt(DOWN_TO_THE_ORIGIN, 5)).isEqualTo(area);
    }

    private static Rgb colour(List<IGeometry> objects, List<Light> lights) {
        Scene scene = scene(objects, lights);
        return new WhittedShader(scene, new LinearTracer(scene)).colourAt(DOWN_TO_THE_ORIGIN, 5);
    }
}
