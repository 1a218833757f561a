package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.scene.Scene;

@DisplayName("A material may be defined anywhere in the file")
class MaterialsAnywhereTest {

    /**
     * Objects that name a material defined above them are built as they are read, the others
     * when the whole file is read: each gets its material, in file order, and the warnings follow.
     */
    @Test
    void givesEachObjectItsMaterialWhereverTheMaterialIsDefined() throws SceneException {
        String source = String.join("\n",
                "orthographic_camera:(0|0|20):(0|0|-1):(50)",
                "sphere:(0|0|0):(1):(255|0|0):(below)",
                "material:(above):(reflective=0.5)",
                "sphere:(1|0|0):(1):(255|0|0):(above)",
                "material:(below):(specular=0.1)",
                "material:(unused):(diffuse=0.5)",
                "triangle:(0|0|0):(1|0|0):(0|1|0):(0|255|0):(above)",
                "sphere:(2|0|0):(1):(0|0|255):(below)");
        List<SceneError> warnings = new ArrayList<>();

        Scene scene = SceneIO.parseScene("scene.txt", source.getBytes(StandardCharsets.UTF_8), Path.of(""), warnings);

        assertThat(scene.objects()).extracting(IGeometry::kind).containsExactly("sphere", "sphere", "triangle", "sphere");
        assertThat(scene.objects()).extracting(object -> object.material().reflective())
                .containsExactly(0f, 0.5f, 0.5f, 0f);
        assertThat(scene.objects()).extracting(object -> object.material().specular())
                .containsExactly(0.1f, Material.DEFAULT.specular(), Material.DEFAULT.specular(), 0.1f);
        assertThat(warnings).extracting(SceneError::message).anySatisfy(message -> assertThat(message).contains("unused"))
                .noneSatisfy(message -> assertThat(message).contains("'above'"));
    }

    /** A material defined twice: the second is a mistake, and an object after both gets the first. */
    @Test
    void reportsAMaterialDefinedTwiceAndTheObjectsMistakes() {
        String source = String.join("\n",
                "orthographic_camera:(0|0|20):(0|0|-1):(50)",
                "material:(m):(reflective=0.5)",
                "material:(m):(reflective=0.25)",
                "sphere:(1|0|0):(-1):(255|0|0):(m)",
                "sphere:(1|0|0):(1):(255|0|0):(n)");
        assertThat(catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt", source)).report())
                .contains("a second material 'm'", "greater than 0", "unknown material 'n'");
    }
}
