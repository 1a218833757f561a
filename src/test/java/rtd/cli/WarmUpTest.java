package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.scene.Scene;

/** The warm-up of the reader and the renderer, whose failures no one would see. */
@DisplayName("The renderer's warm-up")
class WarmUpTest {

    @Test
    void itsSceneIsReadWithoutAMistakeAndHasASphereInView() throws SceneException {
        Scene scene = SceneIO.parseScene("warm-up", WarmUp.SCENE);

        assertThat(scene.objects()).hasSize(1);
        assertThat(scene.camera().generateRay(12, 8, 24, 16).origin().x()).isZero(); // the sphere at the centre
    }

    @Test
    void itRendersOnTheCallingThreadWithoutThrowing() {
        assertThatCode(WarmUp::renderOnce).doesNotThrowAnyException();
    }
}
