package rtd.pov;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.io.ClockedScene;
import rtd.io.SceneException;
import rtd.io.SceneFile;

/** A scene whose numbers use the clock, written with POV-Ray's clock: what rtd works out from them, POV-Ray works out alike. */
@DisplayName("A scene written with POV-Ray's clock")
class PovClockTest {

    private static final String CAMERA = "orthographic_camera:(0|0|10):(0|0|-1):(20)\n";

    private static ClockedScene read(String text) throws SceneException {
        return SceneFile.of("t.txt", text.getBytes(StandardCharsets.UTF_8), Path.of("")).withClock(0);
    }

    private static String pov(String text) throws SceneException {
        return PovScene.of(read(text), 64, 36);
    }

    private static String whyNot(String text) throws SceneException {
        ClockedScene clocked = read(text);
        return PovClock.whyNot(clocked, List.of(clocked.scene().camera()));
    }

    @Test
    void aColourExpressionIsRoundedHalfUpToAWholeNumberOf255ths() throws SceneException {
        assertThat(pov(CAMERA + "sphere:(0|0|0):(1):(255*clock|10|0)\n"))
                .contains("sphere { <0, 0, 0>, 1 pigment { rgb <floor(255 * clock + 0.5) / 255, 0.039215688, 0> }");
    }

    @Test
    void aSpheresCentreAndRadiusFollowTheClock() throws SceneException {
        assertThat(pov(CAMERA + "sphere:(clock|1|2):(1 + clock):(0|0|0)\n")).contains("sphere { <clock, 1, 2>, 1 + clock pigment");
    }

    @Test
    void aPlaneTakesItsUnitNormalAndDistanceFromTheNumbersAsRtdDoes() throws SceneException {
        assertThat(pov(CAMERA + "plane:(0|clock|0):(0|2|clock):(0|0|0)\n"))
                .contains("plane { vnormalize(<0, 2, clock>), vdot(<0, clock, 0>, vnormalize(<0, 2, clock>)) pigment");
    }

    @Test
    void aBoxTakesTheSmallerAndTheLargerOfItsCornersNumbersThatUseTheClock() throws SceneException {
        assertThat(pov(CAMERA + "box:(2|0|1):(1 - clock|1|0):(0|0|0)\n"))
                .contains("box { <min(2, 1 - clock), 0, 0>, <max(2, 1 - clock), 1, 1> pigment");
    }

    @Test
    void aTriangleACylinderAndAConeFollowTheClock() throws SceneException {
        String pov = pov(CAMERA + "triangle:(0|0|0):(1|clock|0):(0|1|0):(0|0|0)\n"
                + "cylinder:(0|0|0):(0|1 + clock|0):(clock + 1):(0|0|0)\n"
                + "cone:(0|0|0):(clock):(0|1|0):(2*clock + 1):(0|0|0)\n");
        assertThat(pov).contains("triangle { <0, 0, 0>, <1, clock, 0>, <0, 1, 0> pigment",
                "cylinder { <0, 0, 0>, <0, 1 + clock, 0>, clock + 1 pigment", "cone { <0, 0, 0>, clock, <0, 1, 0>, 2 * clock + 1 pigment");
    }

    @Test
    void aLightAndTheAmbientLightItAddsToFollowTheClock() throws SceneException {
        String pov = pov(CAMERA + "light:(clock|5|0):(255|255*clock|0)\nlight:(0|5|0):(255|0|0)\n");
        assertThat(pov).contains("light_source { <clock, 5, 0>, rgb <1, floor(255 * clock + 0.5) / 255, 0> }",
                "ambient_light rgb <1 + 1, floor(255 * clock + 0.5) / 255 + 0, 0 + 0>");
    }

    @Test
    void theBackgroundFollowsTheClock() throws SceneException {
        assertThat(pov(CAMERA + "ambient:(0|0|255*clock)\n")).contains("background { rgb <0, 0, floor(255 * clock + 0.5) / 255> }");
    }

    @Test
    void aCameraThatLooksAtAPointWorksOutItsAxesFromTheClockInPovRay() throws SceneException {
        String pov = pov("perspective_camera:(10*sin(360*clock)|2|10):(at 0|1|0):(60 + clock)\n");
        assertThat(pov).contains("#declare Rtd_position = <10 * sin(radians(360 * clock)), 2, 10>;",
                "#declare Rtd_view = <0, 1, 0> - Rtd_position;", "#declare Rtd_right = vnormalize(vcross(Rtd_view, <0, 1, 0>));",
                "#declare Rtd_down = vnormalize(vcross(Rtd_view, Rtd_right));",
                "direction vnormalize(Rtd_view) * 32 / tan(radians(60 + clock) / 2) + Rtd_right * (-0.5) + Rtd_down * (-0.5)",
                "right Rtd_right * 64", "up Rtd_down * (-36)");
    }

    @Test
    void anOrthographicCamerasZoomDividesItsShiftAndItsAxes() throws SceneException {
        String pov = pov("orthographic_camera:(0|0|10):(clock|0|-1):(20 + clock)\n");
        assertThat(pov).contains("#declare Rtd_view = <clock, 0, -1>;",
                "location Rtd_position + Rtd_right * (-0.5) / (20 + clock) + Rtd_down * (-0.5) / (20 + clock)",
                "right Rtd_right * 64 / (20 + clock)", "up Rtd_down * (-36) / (20 + clock)");
    }

    @Test
    void aNumberThatDoesNotUseTheClockIsWrittenAsTheNumberRtdHolds() throws SceneException {
        assertThat(pov(CAMERA + "let:(r):(2*3)\nsphere:(0|clock|0):(r):(0|0|0)\n")).contains("sphere { <0, clock, 0>, 6 pigment");
    }

    @Test
    void everyShapeAndCameraOfTheGrammarCanBeWritten() throws SceneException {
        assertThat(whyNot("perspective_camera:(clock|0|10):(0|0|-1):(60)\nlight:(clock|1|1):(clock|0|0)\nambient:(clock|0|0)\n"
                + "sphere:(clock|0|0):(1):(0|0|0)\nbox:(clock|0|0):(2|1|1):(0|0|0)\n")).isNull();
    }

    @Test
    void aMaterialAPatternOrATransformationThatUsesTheClockIsNotWritten() throws SceneException {
        assertThat(whyNot(CAMERA + "material:(m):(ambient=clock)\nsphere:(0|0|0):(1):(0|0|0):(m)\n"))
                .isEqualTo("the 'material' at line 2");
        assertThat(whyNot(CAMERA + "transform:(spin):(rotate_y 360*clock)\nsphere:(0|0|0):(1):(0|0|0):(spin)\n"))
                .isEqualTo("the 'transform' at line 2");
        assertThat(whyNot(CAMERA + "pattern:(p):(stripes):(255|255|255):(0|0|clock)\nsphere:(0|0|0):(1):(p)\n"))
                .isEqualTo("the 'pattern' at line 2");
    }

    @Test
    void aShapeWithAPatternWhoseNumbersUseTheClockIsNotWritten() throws SceneException {
        assertThat(whyNot(CAMERA + "pattern:(p):(stripes):(255|255|255):(0|0|0)\nsphere:(clock|0|0):(1):(p)\n"))
                .isEqualTo("a sphere with a pattern, which follows its numbers");
    }

    @Test
    void anAreaLightThatUsesTheClockIsNotWritten() throws SceneException {
        assertThat(whyNot(CAMERA + "area_light:(0|5|0):(clock + 1|0|0):(0|0|1):(2|2):(255|255|255)\n"))
                .isEqualTo("the 'area_light' at line 2");
    }

    @Test
    void aCameraThatLooksStraightDownAtSomeFrameIsNotWritten() throws SceneException {
        ClockedScene clocked = read("orthographic_camera:(clock|5|0):(at 0|0|0):(20)\n");
        ClockedScene atOne = read("orthographic_camera:(0|5|0):(at 0|0|0):(20)\n");
        assertThat(PovClock.whyNot(clocked, List.of(clocked.scene().camera(), atOne.scene().camera())))
                .isEqualTo("the camera, which looks straight up or down at a frame");
    }
}
