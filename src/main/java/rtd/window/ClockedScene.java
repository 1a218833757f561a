package rtd.window;

import java.util.ArrayList;
import java.util.function.UnaryOperator;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.scene.Scene;

/**
 * The scene file as the window read it last, parsed at any clock without reading it again (its meshes are read once, by
 * {@link SceneFile}): the clock slider and the play key parse it at each of their values. Each scene parsed is passed
 * through {@code sized}, as the command line sizes it (its {@code --scale}).
 *
 * @param file  the file's bytes, read once
 * @param sized what the command line does to each scene read (the identity for none)
 */
public record ClockedScene(SceneFile file, UnaryOperator<Scene> sized) {

    /** The file's scene at {@code clock} (its warnings are not shown), or its located mistakes at that clock. */
    Scene at(double clock) throws SceneException {
        return sized.apply(file.at(clock, new ArrayList<>()));
    }

    /** Whether a number of the file uses {@code clock}, once it has been parsed. */
    boolean usesClock() {
        return file.usesClock();
    }
}
