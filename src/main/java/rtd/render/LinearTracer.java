package rtd.render;

import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.scene.Scene;

/** The paper's tracer: {@link Scene#nearestHit} tests every object for every ray (Listing 4.3), counted for --stats. */
public final class LinearTracer implements Tracer {

    private final Scene scene;
    private final WorkCount perRay;
    private final int objects;
    private long rays;

    public LinearTracer(Scene scene) {
        this.scene = scene;
        this.perRay = WorkCount.testsOf(scene.objects(), 1);
        this.objects = scene.objects().size();
    }

    @Override
    public Hit nearestHit(Ray ray) {
        rays++;
        return scene.nearestHit(ray);
    }

    @Override
    public WorkCount work() {
        return perRay.times(rays);
    }

    @Override
    public long testsRun() {
        return rays * objects;
    }
}
