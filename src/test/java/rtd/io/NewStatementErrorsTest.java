package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Each mistake in a statement beyond the paper gets its own message at the right line and column. */
@DisplayName("Mistakes in the statements beyond the paper")
class NewStatementErrorsTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";

    static Stream<Arguments> mistakes() {
        return Stream.of(
                Arguments.of("a field of view of 180 degrees", "perspective_camera:(0|0|20):(0|0|-1):(180)", 1, 39,
                        "the field of view must be greater than 0 and less than 180 degrees, found 180"),
                Arguments.of("a field of view of 0", "perspective_camera:(0|0|20):(0|0|-1):(0)", 1, 39,
                        "the field of view must be greater than 0 and less than 180 degrees, found 0"),
                Arguments.of("a perspective camera looking nowhere", "perspective_camera:(0|0|20):(0|0|0):(60)", 1, 30,
                        "the view direction must not be zero, found (0|0|0)"),
                Arguments.of("two cameras of different kinds", CAMERA + "perspective_camera:(0|0|20):(0|0|-1):(60)", 2, 1,
                        "a second camera: a scene has one"),
                Arguments.of("a plane with a zero normal", CAMERA + "plane:(0|0|0):(0|0|0):(1|2|3)", 2, 16,
                        "the normal must not be zero, found (0|0|0)"),
                Arguments.of("a plane with an infinite point", CAMERA + "plane:(0|Infinity|0):(0|1|0):(1|2|3)", 2, 10,
                        "the y of the point must be a finite number, found Infinity"),
                Arguments.of("a triangle on one line", CAMERA + "triangle:(0|0|0):(1|1|1):(2|2|2):(1|2|3)", 2, 10,
                        "the corners of the triangle lie on one line, so it has no area"),
                Arguments.of("a triangle with two equal corners", CAMERA + "triangle:(0|0|0):(0|0|0):(2|1|2):(1|2|3)", 2, 10,
                        "the corners of the triangle lie on one line, so it has no area"),
                Arguments.of("a triangle too large for float", CAMERA + "triangle:(0|0|0):(3e30|0|0):(0|3e30|0):(1|2|3)", 2, 10,
                        "the triangle is too large to compute with in float"),
                Arguments.of("a triangle with a corner too few", CAMERA + "triangle:(0|0|0):(1|0|0):(1|2|3)", 2, 33,
                        "expected ':' before the colour of 'triangle', found the end of the line"),
                Arguments.of("a flat box", CAMERA + "box:(0|0|0):(1|0|1):(1|2|3)", 2, 16,
                        "the box is flat: both corners have y = 0"),
                Arguments.of("a box of one point", CAMERA + "box:(1|1|1):(1.0|1|1):(1|2|3)", 2, 14,
                        "the box is flat: both corners have x = 1.0"),
                Arguments.of("a mesh with a scale of 0", CAMERA + "mesh:(cube.obj):(0|0|0):(0):(1|2|3)", 2, 26,
                        "the scale must be greater than 0, found 0"),
                Arguments.of("a mesh file that is not there", CAMERA + "mesh:( no/such/file.obj ):(0|0|0):(1):(1|2|3)", 2, 8,
                        "cannot read the mesh file 'no/such/file.obj': no such file"),
                Arguments.of("a mesh file that is a folder", CAMERA + "mesh:(src):(0|0|0):(1):(1|2|3)", 2, 7,
                        "cannot read the mesh file 'src': it is a folder, not a file"),
                Arguments.of("a mesh with an empty path", CAMERA + "mesh:( ):(0|0|0):(1):(1|2|3)", 2, 6,
                        "empty group: the file of 'mesh' needs a file path"),
                Arguments.of("a path without ')'", CAMERA + "mesh:(cube.obj", 2, 15,
                        "expected ')' after the path in the file of 'mesh', found the end of the line"),
                Arguments.of("an unknown material", CAMERA + "material:(glass):()\nsphere:(0|0|0):(1):(1|2|3):(glas)", 3, 29,
                        "unknown material 'glas'"),
                Arguments.of("a material used but never defined", CAMERA + "sphere:(0|0|0):(1):(1|2|3):(glass)", 2, 29,
                        "unknown material 'glass'"),
                Arguments.of("a material defined twice", "material:(glass):()\n" + CAMERA + "material:(glass):(ior=1.5)", 3, 11,
                        "a second material 'glass': each name is defined once"),
                Arguments.of("an unknown key", CAMERA + "material:(glass):(difuse=0.5)", 2, 19,
                        "unknown key 'difuse' in the properties of 'material'"),
                Arguments.of("a key given twice", CAMERA + "material:(glass):(ior=1.5|ior=1.4)", 2, 27,
                        "'ior' is given twice in the properties of 'material'"),
                Arguments.of("a key without '='", CAMERA + "material:(glass):(ior 1.5)", 2, 23,
                        "expected '=' after the key 'ior' in the properties of 'material', found '1'"),
                Arguments.of("a value without a key", CAMERA + "material:(glass):(=1.5)", 2, 19,
                        "expected a key such as 'ambient' in the properties of 'material', found '='"),
                Arguments.of("a negative value", CAMERA + "material:(glass):(diffuse=-0.5)", 2, 27,
                        "the value of 'diffuse' must be at least 0, found -0.5"),
                Arguments.of("an index of refraction below 1", CAMERA + "material:(glass):(ior=0.9)", 2, 23,
                        "the value of 'ior' must be at least 1, found 0.9"),
                Arguments.of("an infinite value", CAMERA + "material:(glass):(shininess=Infinity)", 2, 29,
                        "the value of 'shininess' must be a finite number, found Infinity"),
                Arguments.of("a material name with a space", CAMERA + "material:(frosted glass):()", 2, 19,
                        "expected ')' after 'frosted' in the name of 'material', found 'glass'"),
                Arguments.of("a material name of other characters", CAMERA + "sphere:(0|0|0):(1):(1|2|3):(*)", 2, 29,
                        "expected a name in the material of 'sphere', found '*'"),
                Arguments.of("an empty material group", CAMERA + "sphere:(0|0|0):(1):(1|2|3):()", 2, 28,
                        "empty group: the material of 'sphere' needs a name"),
                Arguments.of("a material for a camera", "orthographic_camera:(0|0|20):(0|0|-1):(50):(glass)", 1, 43,
                        "too many groups: 'orthographic_camera' takes 3"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("mistakes")
    void getsAMessageAtItsLineAndColumn(String mistake, String text, int line, int column, String message) {
        List<SceneError> errors = SceneErrorsTest.errorsOf(text).errors();
        assertThat(errors).extracting(SceneError::message).containsExactly(message);
        SceneError error = errors.get(0);
        assertThat(error.line()).as("line").isEqualTo(line);
        assertThat(error.column()).as("column").isEqualTo(column);
        assertThat(error.file()).isEqualTo("scene.txt");
        if (!message.contains("must be a finite number") && !message.contains("must be greater than 0, found")) {
            // as for the paper's radius and zoom, the message says it all
            assertThat(error.help()).as("help").isNotBlank();
        }
    }

    @Test
    void anUnknownMaterialNearADefinedOneIsSuggested() {
        SceneError error = SceneErrorsTest.errorsOf(CAMERA + "sphere:(0|0|0):(1):(1|2|3):(glas)\nmaterial:(glass):()")
                .errors().get(0);
        assertThat(error.help()).isEqualTo("did you mean 'glass'?");
    }

    @Test
    void aMaterialWithAMistakeIsReportedOnceNotAgainAtEachObjectThatUsesIt() {
        List<SceneError> errors = SceneErrorsTest.errorsOf(CAMERA + "sphere:(0|0|0):(1):(1|2|3):(glass)\n"
                + "material:(glass):(ior=0.5)\nmaterial:(metal):(shine=1)\nbox:(0|0|0):(1|1|1):(1|2|3):(metal)").errors();
        assertThat(errors).extracting(SceneError::line).containsExactly(3, 4);
    }

    @Test
    void aKeyInTheWrongCaseIsSuggestedInTheRightOne() {
        SceneError error = SceneErrorsTest.errorsOf(CAMERA + "material:(glass):(IOR=1.5)").errors().get(0);
        assertThat(error.message()).isEqualTo("unknown key 'IOR' in the properties of 'material'");
        assertThat(error.help()).isEqualTo("did you mean 'ior'?");
    }

    @Test
    void anUnknownKeywordSuggestsTheNewStatements() {
        assertThat(SceneErrorsTest.errorsOf(CAMERA + "trianlge:(0|0|0)").errors().get(0).help())
                .isEqualTo("did you mean 'triangle'?");
        assertThat(SceneErrorsTest.errorsOf(CAMERA + "perspective_camra:(0|0|0)").errors().get(0).help())
                .isEqualTo("did you mean 'perspective_camera'?");
        assertThat(SceneErrorsTest.errorsOf(CAMERA + "materal:(a):()").errors().get(0).help())
                .isEqualTo("did you mean 'material'?");
    }

    @Test
    void anObjectWithAnUnknownMaterialStillHasItsOtherMistakesReported() {
        List<SceneError> errors = SceneErrorsTest.errorsOf(CAMERA + "sphere:(0|0|0):(-1):(1|2|3):(glass)").errors();
        assertThat(errors).extracting(SceneError::message)
                .containsExactly("the radius must be greater than 0, found -1", "unknown material 'glass'");
    }
}
