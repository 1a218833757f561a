package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.IGeometry;
import rtd.geometry.Pattern;
import rtd.geometry.Patterned;
import rtd.geometry.Sphere;
import rtd.geometry.Transformed;
import rtd.image.Color;
import rtd.math.Vector3f;
import rtd.scene.Scene;

@DisplayName("Reading patterns, transforms and an object's names")
class PatternsAndTransformsReadingTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";

    private static Scene read(String text) throws SceneException {
        return SceneIO.parseScene("scene.txt", CAMERA + text);
    }

    @Test
    void anObjectNamesItsMaterialAndTransformInEitherOrderDefinedAboveOrBelow() throws SceneException {
        String definitions = "material:(shiny):(reflective=0.5)\ntransform:(up):(translate 0|1|0)\n";
        Scene before = read(definitions + "sphere:(0|0|0):(1):(255|0|0):(shiny):(up)\n");
        Scene after = read("sphere:(0|0|0):(1):(255|0|0):(up):(shiny)\n" + definitions);
        for (Scene scene : new Scene[] {before, after}) {
            IGeometry ball = scene.objects().get(0);
            assertThat(ball).isInstanceOf(Transformed.class);
            assertThat(ball.material().reflective()).isEqualTo(0.5f);
            assertThat(ball.bounds().min().y()).isCloseTo(0f, org.assertj.core.data.Offset.offset(0.01f)); // moved up by 1
        }
    }

    @Test
    void aFileOfOldStatementsMakesTheSameShapesAsEver() throws SceneException {
        Scene scene = read("material:(shiny):(reflective=0.5)\nsphere:(0|0|0):(1):(255|0|0):(shiny)\n");
        assertThat(scene.objects().get(0)).isInstanceOf(Sphere.class);
    }

    @Test
    void aColourGroupNamesAPatternWhoseTransformMayComeLater() throws SceneException {
        Scene scene = read("plane:(0|0|0):(0|1|0):(tiles)\npattern:(tiles):(checker):(255|0|0):(255|255|0):(big)\n"
                + "transform:(big):(scale 2)\n");
        Patterned floor = (Patterned) scene.objects().get(0);
        assertThat(floor.pattern().kind()).isEqualTo(Pattern.Kind.CHECKER);
        // scaled by 2, the tile around (1.5|-0.1|0.5) is (0.75|-0.05|0.25): floor 0 + (−1) + 0 = −1, odd: b
        assertThat(floor.colorAt(new Vector3f(1.5f, -0.1f, 0.5f))).isEqualTo(new Color(255, 255, 0));
        assertThat(floor.colorAt(new Vector3f(2.5f, -0.1f, 0.5f))).isEqualTo(new Color(255, 0, 0));
    }

    @Test
    void aPatternedTransformedObjectIsPaintedInItsOwnSpace() throws SceneException {
        Scene scene = read("sphere:(0|0|0):(1):(bands):(right)\npattern:(bands):(stripes):(0|0|0):(255|255|255)\n"
                + "transform:(right):(translate 10|0|0)\n");
        IGeometry ball = scene.objects().get(0);
        assertThat(ball.isPatterned()).isTrue();
        assertThat(ball.colorAt(new Vector3f(10.5f, 0, 0))).isEqualTo(new Color(0, 0, 0));   // x = 0.5 in its space
        assertThat(ball.colorAt(new Vector3f(9.5f, 0, 0))).isEqualTo(new Color(255, 255, 255)); // x = −0.5
    }

    @Test
    void aTransformedMeshTransformsEachTriangle() throws SceneException {
        Scene scene = SceneIO.parseScene("scene.txt", (CAMERA + "transform:(up):(translate 0|5|0)\n"
                + "mesh:(meshes/icosphere_0.obj):(0|0|0):(1):(200|60|50):(up)\n").getBytes(StandardCharsets.UTF_8),
                Path.of("examples"), null);
        assertThat(scene.objects()).hasSize(20).allSatisfy(t -> assertThat(t).isInstanceOf(Transformed.class));
        assertThat(scene.objects().get(0).bounds().min().y()).isGreaterThan(3.9f);
    }

    @Test
    void stepsApplyInTheOrderWritten() throws SceneException {
        // scale 2, then translate 1|0|0: the unit sphere reaches from x = -1 to 3; the other order from 0 to 4
        Scene scene = read("transform:(a):(scale 2):(translate 1|0|0)\ntransform:(b):(translate 1|0|0):(scale 2)\n"
                + "sphere:(0|0|0):(1):(1|1|1):(a)\nsphere:(0|0|0):(1):(1|1|1):(b)\n");
        assertThat(scene.objects().get(0).bounds().min().x()).isCloseTo(-1f, org.assertj.core.data.Offset.offset(0.01f));
        assertThat(scene.objects().get(1).bounds().min().x()).isCloseTo(0f, org.assertj.core.data.Offset.offset(0.01f));
    }

    @Test
    void aPatternOrTransformThatNothingNamesIsWarnedOfButOneAPatternNamesIsNot() throws SceneException {
        java.util.List<SceneError> warnings = new java.util.ArrayList<>();
        SceneIO.parseScene("scene.txt", (CAMERA + "transform:(big):(scale 2)\ntransform:(lift):(translate 0|1|0)\n"
                + "pattern:(tiles):(checker):(255|0|0):(255|255|0):(big)\npattern:(spare):(rings):(0|0|0):(9|9|9)\n"
                + "plane:(0|0|0):(0|1|0):(tiles)\n").getBytes(StandardCharsets.UTF_8), Path.of(""), warnings);
        assertThat(warnings).extracting(SceneError::message).containsExactly(
                "transform 'lift' is defined, but no object or pattern names it",
                "pattern 'spare' is defined, but no object names it");
    }

    @Test
    void aKindOrStepOrKeyFarFromEveryWordGetsTheListOfWords() {
        assertThat(helpFor("pattern:(p):(zzzzzz):(0|0|0):(9|9|9)"))
                .isEqualTo("the kinds are 'stripes', 'gradient', 'rings' and 'checker'");
        assertThat(helpFor("transform:(t):(zzzzzz 2)"))
                .isEqualTo("the steps are 'scale', 'rotate_x', 'rotate_y', 'rotate_z' and 'translate'");
        assertThat(helpFor("material:(m):(zzzzzz=1)")).isEqualTo("the keys are 'ambient', 'diffuse', 'specular', "
                + "'shininess', 'reflective', 'transparency' and 'ior'");
    }

    private static String helpFor(String line) {
        try {
            read(line + "\n");
        } catch (SceneException e) {
            return e.errors().get(0).help();
        }
        throw new AssertionError("no mistake in " + line);
    }
}
