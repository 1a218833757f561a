package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Sphere;
import rtd.math.Vector3f;
import rtd.image.Color;
import rtd.scene.Scene;

/** What a person expects to be fine is fine. */
@DisplayName("Lenient reading of scene files")
class LenientReadingTest {

    private static final Sphere EXPECTED = new Sphere(new Vector3f(3, 8, -1), 2, new Color(0, 127, 255));

    private static Scene read(String text) throws SceneException {
        return SceneIO.parseScene("scene.txt", text);
    }

    @Test
    void thePapersExampleReadsAsListingA1Says() throws Exception {
        Scene scene = SceneIO.readScene(java.nio.file.Path.of("examples", "input_rtd.txt"));
        assertThat(scene.ambient()).isEqualTo(new Color(127, 255, 255));
        OrthographicCamera camera = (OrthographicCamera) scene.camera();
        assertThat(camera.position()).isEqualTo(new Vector3f(0, 0, 20));
        assertThat(camera.direction()).isEqualTo(new Vector3f(0, 0, -1));
        assertThat(camera.zoom()).isEqualTo(50f);
        assertThat(scene.objects()).containsExactly(EXPECTED,
                new Sphere(new Vector3f(-10, 1, 5), 5, new Color(255, 0, 0)));
    }

    @Test
    void aByteOrderMarkWindowsLineEndsTabsAndSpacesAreFine() throws SceneException {
        String text = "\uFEFF  orthographic_camera : ( 0 | 0 | 20 ) :\t(0|0|-1):(50)\r\n\r\n\t sphere\t:\t(\t3 |8| -1 ) : ( 2 ) : (0 | 127 | 255 )  \r\n";
        Scene scene = SceneIO.parseScene("scene.txt", text.getBytes(StandardCharsets.UTF_8), Path.of(""), null);
        assertThat(scene.objects()).containsExactly(EXPECTED);
    }

    @Test
    void aCommentAfterAStatementIsFine() throws SceneException {
        Scene scene = read("orthographic_camera:(0|0|20):(0|0|-1):(50) // the camera\nsphere:(3|8|-1):(2):(0|127|255)// blue");
        assertThat(scene.objects()).containsExactly(EXPECTED);
    }

    @Test
    void numbersMayBeWrittenInEveryUsualWay() throws SceneException {
        Scene scene = read("orthographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(3.|+8|-1.0e0):(.2e1):(0|1.27e2|255.)\nsphere:(-0|2e3|1E-3):(0.5):(0|0|0)");
        assertThat(scene.objects().get(0)).isEqualTo(EXPECTED);
        Sphere second = (Sphere) scene.objects().get(1);
        assertThat(second.center()).isEqualTo(new Vector3f(-0f, 2000, 0.001f));
        assertThat(second.radius()).isEqualTo(0.5f);
    }

    @Test
    void aSceneWithoutAmbientHasABlackBackgroundAndOneWithoutSpheresIsFine() throws SceneException {
        Scene scene = read("orthographic_camera:(0|0|20):(0|0|-1):(50)");
        assertThat(scene.ambient()).isEqualTo(Color.BLACK);
        assertThat(scene.objects()).isEmpty();
    }

    @Test
    void aLastLineWithoutLineBreakIsRead() throws SceneException {
        assertThat(read("orthographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(3|8|-1):(2):(0|127|255)").objects())
                .containsExactly(EXPECTED);
    }
}
