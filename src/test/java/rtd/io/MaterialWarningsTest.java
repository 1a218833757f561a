package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/** The slips with materials that are no mistakes: told as warnings at the material's line, in file order. */
@DisplayName("The warnings about materials")
class MaterialWarningsTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";

    private static List<String> warnings(String scene) throws SceneException {
        List<SceneError> warnings = new ArrayList<>();
        SceneIO.parseScene("scene.txt", scene.getBytes(StandardCharsets.UTF_8), Path.of(""), warnings);
        return warnings.stream().map(w -> w.line() + ":" + w.column() + " " + w.message()).toList();
    }

    @Test
    void aLitSceneWhoseMaterialsAreAllNamedAndLetLightThroughWhereTheyBendItHasNone() throws SceneException {
        assertThat(warnings(CAMERA + "sphere:(0|0|0):(1):(255|0|0):(glass)\nlight:(0|9|9):(255|255|255)\n"
                + "material:(glass):(transparency=0.9|ior=1.5)\nmaterial:(mirror):(reflective=1)\n"
                + "plane:(0|-1|0):(0|1|0):(9|9|9):(mirror)\n")).isEmpty();
    }

    @Test
    void eachSlipIsToldAtItsMaterialInFileOrder() throws SceneException {
        assertThat(warnings(CAMERA + "material:(a):(ior=2)\nsphere:(0|0|0):(1):(255|0|0):(a)\nmaterial:(b):(diffuse=0.5)\n"
                + "light:(0|9|9):(255|255|255)\n")).containsExactly(
                        "2:15 the ior of material 'a' bends nothing: its transparency is 0, so no light goes through it",
                        "4:11 material 'b' is defined, but no object names it");
        assertThat(warnings(CAMERA + "material:(a):(ior=2)\nsphere:(0|0|0):(1):(255|0|0):(a)\nmaterial:(b):(diffuse=0.5)\n"))
                .containsExactly("2:11 materials change nothing here: the scene has no light, so it is drawn in flat colours, "
                        + "as in the paper", "4:11 material 'b' is defined, but no object names it");
    }

    @Test
    void theIorIsPointedAtWhereverItStandsAmongTheProperties() throws SceneException {
        // a material may be named ior too: the key is the word before '=', not the name
        assertThat(warnings(CAMERA + "light:(0|9|9):(255|255|255)\nmaterial:(ior):( diffuse=0.5 |  ior = 1.5)\n"
                + "sphere:(0|0|0):(1):(255|0|0):(ior)\n"))
                .containsExactly("3:33 the ior of material 'ior' bends nothing: its transparency is 0, so no light goes through it");
    }

    @Test
    void atMost20AreShownAndALastLineCountsTheRest() throws SceneException {
        StringBuilder scene = new StringBuilder(CAMERA + "light:(0|9|9):(255|255|255)\nsphere:(0|0|0):(1):(255|0|0):(m0)\n");
        for (int m = 0; m < 300; m++) {
            scene.append("material:(m").append(m).append("):(ior=1.2)\n");
        }
        List<String> shown = warnings(scene.toString());
        assertThat(shown).hasSize(21);
        assertThat(shown.get(0)).isEqualTo("4:16 the ior of material 'm0' bends nothing: its transparency is 0, so no light goes "
                + "through it");
        assertThat(shown.get(20)).isEqualTo("14:17 and 579 more warnings like these, the first of them here");
    }

    @Test
    void withoutALightTheIorIsNotToldAsIfItCouldBend() throws SceneException {
        assertThat(warnings(CAMERA + "material:(a):(ior=2)\nsphere:(0|0|0):(1):(255|0|0):(a)\n")).hasSize(1)
                .allMatch(w -> w.contains("the scene has no light"));
    }

    @Test
    void aSceneWithAMistakeTellsTheMistakeAlone() {
        List<SceneError> warnings = new ArrayList<>();
        SceneException e = catchThrowableOfType(SceneException.class,
                () -> SceneIO.parseScene("scene.txt", (CAMERA + "material:(b):(diffuse=0.5)\n"
                        + "spere:(0|0|0):(1):(255|0|0)\n").getBytes(StandardCharsets.UTF_8), Path.of(""), warnings));
        assertThat(e.errors()).hasSize(1);
        assertThat(warnings).isEmpty();
    }
}
