package rtd.window;

import java.io.IOException;
import java.nio.file.Path;

/**
 * What the command line gives the window: the scene file, how to read it and watch it, what to trace with, and the
 * picture's size, samples and threads as {@code -o} would render it.
 *
 * @param scene   the scene file, as the user spelt it
 * @param loader  reads it
 * @param watch   tells of each save
 * @param engine  the tracers {@code --accel} chose
 * @param width   the picture's width in pixels
 * @param height  the picture's height in pixels
 * @param samples {@code --samples}: rays per pixel, each way, of the full picture
 * @param threads {@code --threads}
 * @param clock   {@code --clock}: the clock the window starts at, between 0 and 1 for its slider
 */
public record WindowSetup(Path scene, SceneLoader loader, FileWatch watch, Engine engine, int width, int height,
        int samples, int threads, double clock) {

    /** Reads the window's scene file, as the command line reads it; again after each save. */
    @FunctionalInterface
    public interface SceneLoader {

        /**
         * The scene file as it is now, read once, to be parsed at any clock; a file that cannot be read throws an
         * {@link IOException} whose message says so for people ("cannot read the scene file '…': …").
         */
        ClockedScene read() throws IOException;
    }

    /** Where {@code Ctrl+S} saves: beside the scene, its name with {@code -window.png} for its extension. */
    Path savedPicture() {
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String stem = dot > 0 ? name.substring(0, dot) : name;
        return scene.resolveSibling(stem + "-window.png");
    }
}
