package rtd.window;

import java.io.IOException;
import rtd.io.SceneException;
import rtd.scene.Scene;

/** Reads the window's scene file, as the command line reads it (at its {@code --scale}); again after each save. */
@FunctionalInterface
public interface SceneLoader {

    /**
     * The scene as the file holds it now, or its located mistakes; a file that cannot be read throws an
     * {@link IOException} whose message says so for people ("cannot read the scene file '…': …").
     */
    Scene load() throws SceneException, IOException;
}
