package rtd.render;

import rtd.math.Ray;
import rtd.scene.Color;
import rtd.scene.Scene;

/**
 * The paper's tracer: {@link Scene#trace} tests every object for every ray (Listing 4.3).
 * This class only counts that work for {@code --stats}.
 */
public final class LinearTracer implements Tracer {

    private final Scene scene;
    private long rays;

    /** A tracer for {@code scene}. */
    public LinearTracer(Scene scene) {
        this.scene = scene;
    }

    @Override
    public Color trace(Ray ray) {
        rays++;
        return scene.trace(ray);
    }

    /** Every ray is tested against every object. */
    @Override
    public WorkCount work() {
        return new WorkCount(rays, rays * scene.objects().size(), 0);
    }
}
