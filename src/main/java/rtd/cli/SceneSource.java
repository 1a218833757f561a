package rtd.cli;

import java.io.IOException;
import java.nio.file.Path;
import rtd.io.SceneFile;
import rtd.io.SceneIO;

/** Where a scene comes from: a file as the user spelt it, or standard input for {@code -}. */
record SceneSource(Path path, boolean stdin) {

    static SceneSource of(Path path) {
        return new SceneSource(path, path.toString().equals("-"));
    }

    /** The name for messages: the path as spelt, or {@code <stdin>}. */
    String name() {
        return stdin ? SceneIO.STDIN_NAME : path.toString();
    }

    /** Reads the scene file once, to be parsed at each clock of an animation with at most {@code threads} threads. */
    SceneFile readFile(StandardStreams streams, int threads) throws FileError {
        try {
            SceneFile file = !stdin ? SceneFile.read(path) : streams.inPath().isPresent()
                    ? SceneFile.read(streams.inPath().get(), SceneIO.STDIN_NAME, Path.of(""))
                    : SceneFile.read(streams.in(), SceneIO.STDIN_NAME);
            return file.onThreads(threads);
        } catch (IOException e) {
            throw new FileError("cannot read the scene file '" + name() + "'", e);
        }
    }
}
