package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.IGeometry;
import rtd.geometry.Transformed;
import rtd.io.ClockedScene.ClockFields;

/** A scene read with the expressions of its numbers that use the clock beside it, for the POV-Ray export of an animation. */
@DisplayName("A scene read with its clock's expressions")
class ClockedSceneTest {

    private static final String CAMERA = "orthographic_camera:(0|0|10):(0|0|-1):(20)\n";

    private static ClockedScene read(String text, double clock) throws SceneException {
        return SceneFile.of("t.txt", text.getBytes(StandardCharsets.UTF_8), Path.of("")).withClock(clock);
    }

    @Test
    void aSceneOfPlainNumbersHasNoExpressions() throws SceneException {
        ClockedScene clocked = read(CAMERA + "sphere:(0|1|2):(2*3):(255|0|0)\n", 0);
        assertThat(clocked.of(clocked.scene().objects().get(0)).isEmpty()).isTrue();
        assertThat(clocked.camera().isEmpty() && clocked.parts().isEmpty() && clocked.unwritten().isEmpty()).isTrue();
    }

    @Test
    void eachNumberThatUsesTheClockIsFoundByItsGroupAndPlace() throws SceneException {
        ClockedScene clocked = read(CAMERA + "let:(up):(2*clock)\nsphere:(1|up|2*3):(1 + clock):(255|0|0)\n", 0.5);
        ClockFields sphere = clocked.of(clocked.scene().objects().get(0));
        assertThat(sphere.groups()).containsExactlyInAnyOrder("centre", "radius");
        assertThat(sphere.of("centre", 0)).isNull();
        assertThat(sphere.of("centre", 1)).isInstanceOf(Expression.Name.class);
        assertThat(sphere.of("centre", 2)).as("2*3 does not use the clock").isNull();
        assertThat(sphere.value("centre", 1)).isEqualTo(1f);
        assertThat(sphere.value("radius", 0)).isEqualTo(1.5f);
        assertThat(sphere.value("colour", 0)).isEqualTo(255f);
    }

    @Test
    void theCameraTheAmbientAndALightHaveTheirOwn() throws SceneException {
        ClockedScene clocked = read("orthographic_camera:(clock|0|10):(0|0|-1):(20)\nambient:(0|0|255*clock)\n"
                + "light:(0|clock|0):(255|255|255)\n", 0);
        assertThat(clocked.camera().groups()).containsExactly("position");
        assertThat(clocked.ambient().groups()).containsExactly("colour");
        assertThat(clocked.of(clocked.scene().lights().get(0)).groups()).containsExactly("position");
    }

    @Test
    void anObjectThatNamesAMaterialDefinedBelowItIsFoundAsTheSceneHoldsIt() throws SceneException {
        ClockedScene clocked = read(CAMERA + "transform:(t):(scale 2)\nsphere:(clock|0|0):(1):(255|0|0):(shiny):(t)\n"
                + "material:(shiny):(specular=1)\n", 0);
        IGeometry object = clocked.scene().objects().get(0);
        assertThat(object).isInstanceOf(Transformed.class);
        assertThat(clocked.of(object).groups()).containsExactly("centre");
        assertThat(clocked.unwritten()).isEmpty();
    }

    @Test
    void aStatementWhoseClockIsNotCarriedIsListed() throws SceneException {
        ClockedScene clocked = read(CAMERA + "material:(m):(ambient=clock)\nsphere:(0|0|0):(1):(0|0|0):(m)\n", 0);
        assertThat(clocked.unwritten()).containsExactly("the 'material' at line 2");
    }

    /** Steps of one transform all mean "step": each is filed apart, the second as "step 2". */
    @Test
    void eachStepOfATransformThatUsesTheClockIsFiledApart() throws SceneException {
        ClockedScene clocked = read(CAMERA + "transform:(spin):(rotate_y 90*clock):(translate 0|clock|0)\n"
                + "box:(-1|0|-1):(1|1|1):(230|120|40):(spin)\n", 0.5);
        assertThat(clocked.unwritten()).containsExactly("the 'transform' at line 2");
    }
}
