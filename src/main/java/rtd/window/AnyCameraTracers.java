package rtd.window;

import java.util.function.Supplier;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * The tracers for any camera of the last scene asked for, built again only for another scene (a save, a new clock),
 * not for another camera. Used on the render thread only.
 */
final class AnyCameraTracers {

    private final WindowSetup setup;
    private Scene scene;
    private Supplier<Tracer> tracers;

    AnyCameraTracers(WindowSetup setup) {
        this.setup = setup;
    }

    /** The tracers for {@code objects}, whatever its camera. */
    Supplier<Tracer> of(Scene objects) {
        if (scene != objects) {
            tracers = setup.engine().forAnyCamera(objects, setup.width(), setup.height());
            scene = objects;
        }
        return tracers;
    }
}
