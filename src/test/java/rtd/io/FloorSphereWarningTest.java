package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/** A sphere so large that it shows shadow acne warns at its radius, in a lit scene only. */
@DisplayName("A huge sphere used as a floor")
class FloorSphereWarningTest {

    private static final String CAMERA = "perspective_camera:(0|2|10):(at 0|1|0):(60)\n";
    private static final String LIGHT = "light:(10|20|20):(255|255|255)\n";

    private static List<SceneError> warnings(String text) throws SceneException {
        List<SceneError> warnings = new ArrayList<>();
        SceneIO.parseScene("scene.txt", text.getBytes(StandardCharsets.UTF_8), Path.of(""), warnings);
        return warnings;
    }

    @Test
    void warnsAtItsRadiusInALitScene() throws SceneException {
        List<SceneError> warnings = warnings(CAMERA + LIGHT + "sphere:(0|-10000|0):(10000):(235|235|245)\n");
        assertThat(warnings).hasSize(1);
        assertThat(warnings.get(0).line()).isEqualTo(3);
        assertThat(warnings.get(0).column()).isEqualTo(22);
        assertThat(warnings.get(0).message()).contains("shadow acne");
        assertThat(warnings.get(0).help()).contains("plane:");
    }

    @Test
    void warnsFromARadiusOf5000AlsoWithAMaterialDefinedBelow() throws SceneException {
        assertThat(warnings(CAMERA + LIGHT + "sphere:(0|-5000|0):(5000):(235|235|245):(m)\nmaterial:(m):(diffuse=0.5)\n"))
                .extracting(SceneError::line).containsExactly(3);
        assertThat(warnings(CAMERA + LIGHT + "sphere:(0|-4999|0):(4999):(235|235|245)\n")).isEmpty();
    }

    @Test
    void saysNothingWithoutALightSinceNothingCastsAShadow() throws SceneException {
        assertThat(warnings(CAMERA + "sphere:(0|-10000|0):(10000):(235|235|245)\n")).isEmpty();
    }
}
