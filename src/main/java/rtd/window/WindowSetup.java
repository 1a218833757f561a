package rtd.window;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.function.Supplier;
import java.util.function.UnaryOperator;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * What the command line gives the window: the scene file, how to read it and watch it, what to trace with, and the
 * picture's size, {@code --samples} and {@code --threads} as {@code -o} would render it; {@code clock} is
 * {@code --clock}, where the window's clock starts, between 0 and 1 for its slider.
 */
public record WindowSetup(Path scene, SceneLoader loader, FileWatch watch, Engine engine, int width, int height,
        int samples, int threads, double clock) {

    /**
     * Reads the window's scene file as the command line reads it, again after each save; a file that cannot be read
     * throws an {@link IOException} whose message says so for people ("cannot read the scene file '…': …").
     */
    @FunctionalInterface
    public interface SceneLoader {
        ClockedScene read() throws IOException;
    }

    /** {@code --watch}'s watcher: {@code changed} runs after each save of the scene or its meshes, until closed. */
    @FunctionalInterface
    public interface FileWatch {
        AutoCloseable start(Runnable changed);
    }

    /**
     * What the window finds its hits with, as {@code --accel} chose (every choice draws the same pixels):
     * {@code forAnyCamera} the tracers for rays of any camera in a scene, built once and kept while the camera moves;
     * {@code forPicture} those {@code -o} takes for the full picture by the scene's camera, built from
     * {@code anyCamera} so that only what serves this camera alone is built again. A new tracer for each thread.
     */
    public interface Engine {
        Supplier<Tracer> forPicture(Scene scene, int width, int height, int samples, Supplier<Tracer> anyCamera);

        Supplier<Tracer> forAnyCamera(Scene scene, int width, int height);
    }

    /**
     * The scene file as the window read it last, parsed at any clock without reading it again (its meshes are read
     * once, by {@link SceneFile}), each scene passed through {@code sized} as the command line sizes it
     * ({@code --scale}; the identity for none).
     */
    public record ClockedScene(SceneFile file, UnaryOperator<Scene> sized) {

        /** The file's scene at {@code clock} (its warnings are not shown), or its located mistakes at that clock. */
        Scene at(double clock) throws SceneException {
            return sized.apply(file.at(clock, new ArrayList<>()));
        }
    }

    /** Where {@code Ctrl+S} saves: beside the scene, its name with {@code -window.png} for its extension. */
    Path savedPicture() {
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return scene.resolveSibling((dot > 0 ? name.substring(0, dot) : name) + "-window.png");
    }
}
