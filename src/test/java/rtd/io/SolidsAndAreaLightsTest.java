package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.scene.Light;
import rtd.scene.Scene;

/** The statements of cylinders, cones and area lights read into what they name, and their mistakes located. */
@DisplayName("The cylinder, cone and area_light statements")
class SolidsAndAreaLightsTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";

    private static Scene read(String text) throws SceneException {
        return SceneIO.parseScene("scene.txt", text);
    }

    @Test
    void aCylinderHasItsEndsRadiusColourAndMaterial() throws SceneException {
        Scene scene = read(CAMERA + "cylinder:(1|2|3):(1|5|3):(0.5):(10|20|30):(m)\nmaterial:(m):(reflective=0.5)");
        assertThat(scene.objects()).containsExactly(new Cylinder(new Vector3f(1, 2, 3), new Vector3f(1, 5, 3), 0.5f,
                new Color(10, 20, 30), new Material(0.1f, 0.9f, 0.9f, 200, 0.5f, 0, 1)));
    }

    @Test
    void aConeHasItsEndsAndRadiiInTheOrderWritten() throws SceneException {
        Scene scene = read(CAMERA + "cone:(0|0|0):(1):(0|2|0):(0):(10|20|30)");
        assertThat(scene.objects()).containsExactly(new Cone(Vector3f.ZERO, 1, new Vector3f(0, 2, 0), 0,
                new Color(10, 20, 30), Material.DEFAULT));
    }

    /**
     * Corner (0|4|0), u = (2|0|0), v = (0|0|1), 2 × 2 samples of (255|255|255): lights at
     * C + (i + ½)/2·u + (j + ½)/2·v = (0.5|4|0.25), (0.5|4|0.75), (1.5|4|0.25), (1.5|4|0.75), each a quarter of white.
     */
    @Test
    void anAreaLightIsItsSamplesEachAShareOfItsIntensity() throws SceneException {
        Scene scene = read(CAMERA + "light:(9|9|9):(255|0|0)\narea_light:(0|4|0):(2|0|0):(0|0|1):(2|2):(255|255|255)");
        List<Light> lights = scene.lights();
        assertThat(lights).hasSize(5);
        assertThat(lights.get(0).area()).as("a point light of its own").isNull();
        assertThat(lights.subList(1, 5)).extracting(Light::position).containsExactly(new Vector3f(0.5f, 4, 0.25f),
                new Vector3f(0.5f, 4, 0.75f), new Vector3f(1.5f, 4, 0.25f), new Vector3f(1.5f, 4, 0.75f));
        assertThat(lights.subList(1, 5)).extracting(Light::intensity).containsOnly(new Rgb(0.25f, 0.25f, 0.25f));
        assertThat(lights.get(1).area()).isSameAs(lights.get(4).area());
        assertThat(lights.get(1).area().sampleCount()).isEqualTo(4);
    }

    @Test
    void aCylinderOfRadius0OrWithOneEndTwiceIsAnErrorAtItsValue() {
        SceneError radius = SceneErrorsTest.errorsOf(CAMERA + "cylinder:(0|0|0):(0|2|0):(0):(1|2|3)").errors().get(0);
        assertThat(radius.message()).isEqualTo("the radius must be greater than 0, found 0");
        assertThat(radius.column()).isEqualTo(27);
        SceneError ends = SceneErrorsTest.errorsOf(CAMERA + "cylinder:(1|1|1):(1|1|1):(1):(1|2|3)").errors().get(0);
        assertThat(ends.message()).isEqualTo("the cylinder's two end points are the same point");
        assertThat(ends.column()).isEqualTo(18);
    }

    @Test
    void aConeNeedsARadiusAbove0AndNoneBelow() {
        SceneError both = SceneErrorsTest.errorsOf(CAMERA + "cone:(0|0|0):(0):(0|2|0):(0):(1|2|3)").errors().get(0);
        assertThat(both.message()).isEqualTo("the cone's radii are both 0, so it has no volume");
        assertThat(both.column()).isEqualTo(27);
        SceneError negative = SceneErrorsTest.errorsOf(CAMERA + "cone:(0|0|0):(1):(0|2|0):(-2):(1|2|3)").errors().get(0);
        assertThat(negative.message()).isEqualTo("the second radius must be at least 0, found -2");
        assertThat(negative.column()).isEqualTo(27);
    }

    @Test
    void anAreaLightTakes1To32WholeSamplesAlongEachEdge() {
        for (String samples : List.of("0|4", "33|4", "4|1.5", "4|-1")) {
            SceneError error = SceneErrorsTest.errorsOf(CAMERA + "area_light:(0|4|0):(2|0|0):(0|0|1):(" + samples
                    + "):(255|255|255)").errors().get(0);
            assertThat(error.message()).as(samples).contains("must be a whole number from 1 to 32, found "
                    + (samples.startsWith("4|") ? samples.substring(2) : samples.substring(0, samples.indexOf('|'))));
        }
    }
}
