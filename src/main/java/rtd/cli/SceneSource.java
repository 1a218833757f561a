package rtd.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import rtd.io.SceneError;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.scene.Scene;

/**
 * Where a scene comes from: a file, or standard input for {@code -}.
 *
 * @param path the file as the user spelt it, or {@code -}
 */
record SceneSource(Path path, boolean stdin) {

    static SceneSource of(Path path) {
        return new SceneSource(path, path.toString().equals("-"));
    }

    /** The name for messages: the path as spelt, or {@code <stdin>}. */
    String name() {
        return stdin ? SceneIO.STDIN_NAME : path.toString();
    }

    /** Reads the scene; its warnings (slips that are no mistakes) go to {@code warnings}. */
    Scene read(StandardStreams streams, List<SceneError> warnings) throws SceneException, FileError {
        try {
            if (!stdin) {
                return SceneIO.readScene(path, warnings);
            }
            return streams.inPath().isPresent() ? SceneIO.readScene(streams.inPath().get(), SceneIO.STDIN_NAME, warnings)
                    : SceneIO.readScene(streams.in(), SceneIO.STDIN_NAME, warnings);
        } catch (IOException e) {
            throw new FileError("cannot read the scene file '" + name() + "'", e);
        }
    }
}
