package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.io.SceneIO;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.scene.Scene;

@DisplayName("The camera line the window copies")
class CameraLineTest {

    @Test
    void itIsTheSceneFilesStatementWithPlainNumbers() {
        assertThat(CameraController.line(new PerspectiveCamera(new Vector3f(0, 2.5f, 9), new Vector3f(0, -0.3f, -1),
                60)))
                .isEqualTo("perspective_camera:(0|2.5|9):(0|-0.3|-1):(60)");
        assertThat(CameraController.line(new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50)))
                .isEqualTo("orthographic_camera:(0|0|20):(0|0|-1):(50)");
        assertThat(CameraController.number(1e-9f)).isEqualTo("0.000000001");
        assertThat(CameraController.number(0.1f)).isEqualTo("0.1");
    }

    @Test
    void theSceneWithTheCopiedLineRendersTheWindowsPicture() throws Exception {
        for (String name : new String[] {"glass_and_mirror", "input_rtd"}) {
            String text = Files.readString(Path.of("examples", name + ".txt"));
            Scene scene = SceneIO.parseScene(name, text);
            CameraController controller = new CameraController(scene.camera());
            controller.orbit(0.61, 0.17, new Vector3f(0.3f, 0.7f, -1.1f));
            controller.pan(7, -3, Vector3f.ZERO, 160);
            controller.zoom(1.5, Vector3f.ZERO);
            Scene moved = new Scene(scene.ambient(), controller.camera(), scene.objects(), scene.lights());
            String line = CameraController.line(moved.camera());
            String pasted = text.replaceAll("(?m)^(perspective|orthographic)_camera:.*$", line);
            Scene fromFile = SceneIO.parseScene(name, pasted);
            assertThat(render(fromFile)).as(line).isEqualTo(render(moved));
        }
    }

    private static int[] render(Scene scene) {
        return ParallelRenderer.render(scene.camera(), () -> new LinearTracer(scene),
                FrameRenderer.shaders(scene, null), 160, 90, 1, new RenderProgress()).image().rgb();
    }
}
