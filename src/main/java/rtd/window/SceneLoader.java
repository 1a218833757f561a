package rtd.window;

import java.io.IOException;

/** Reads the window's scene file, as the command line reads it; again after each save. */
@FunctionalInterface
public interface SceneLoader {

    /**
     * The scene file as it is now, read once, to be parsed at any clock; a file that cannot be read throws an
     * {@link IOException} whose message says so for people ("cannot read the scene file '…': …").
     */
    ClockedScene read() throws IOException;
}
