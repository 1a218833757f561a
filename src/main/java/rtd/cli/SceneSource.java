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
 * @param path  the file as the user spelt it, or {@code -}
 * @param stdin whether it is standard input
 */
record SceneSource(Path path, boolean stdin) {

    /** The name of standard input in messages, as compilers call it. */
    static final String STDIN_NAME = "<stdin>";

    /** The scene named {@code path} on the command line; {@code -} is standard input. */
    static SceneSource of(Path path) {
        return new SceneSource(path, path.toString().equals("-"));
    }

    /** The name for messages: the path as spelt, or {@code <stdin>}. */
    String name() {
        return stdin ? STDIN_NAME : path.toString();
    }

    /** Reads and parses the scene; its warnings (slips that are no mistakes) go to {@code warnings}. */
    Scene read(StandardStreams streams, List<SceneError> warnings) throws SceneException, IOException {
        if (!stdin) {
            return SceneIO.readScene(path, warnings);
        }
        if (streams.inPath().isPresent()) {
            return SceneIO.readScene(streams.inPath().get(), STDIN_NAME, warnings);
        }
        return SceneIO.readScene(streams.in(), STDIN_NAME, warnings);
    }
}
