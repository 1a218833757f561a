package rtd.window;

import java.util.function.Supplier;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * What the window finds its hits with, given by the command line, which knows {@code --accel}: the window renders
 * through the {@link Tracer} interface alone. Every tracer finds the same hits, so every choice draws the same pixels;
 * they differ in what they cost to build and to trace.
 */
public interface Engine {

    /**
     * Tracers for the full {@code width × height} picture of {@code scene} by its camera with {@code samples × samples}
     * rays per pixel, as {@code -o} chooses them; a new tracer for each thread. What serves any camera comes from
     * {@code anyCamera} (built once for the scene), so that only what serves this camera alone is built again.
     */
    Supplier<Tracer> forPicture(Scene scene, int width, int height, int samples, Supplier<Tracer> anyCamera);

    /**
     * Tracers for rays of any camera in {@code scene}'s objects and lights, for pictures of about
     * {@code width × height}, built once for a scene and kept while the camera moves (coarse passes and moving frames,
     * whose rays a camera's grid does not serve).
     */
    Supplier<Tracer> forAnyCamera(Scene scene, int width, int height);
}
