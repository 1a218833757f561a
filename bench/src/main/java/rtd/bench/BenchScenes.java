package rtd.bench;

import java.util.ArrayList;
import java.util.List;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.image.Color;
import rtd.scene.Scene;

/** The benchmark scenes of {@link SceneGenerator}, built in memory. */
final class BenchScenes {

    static final int WIDTH = 1920;
    static final int HEIGHT = 1080;

    private BenchScenes() {
    }

    static Scene randomSpheres(int count) {
        List<IGeometry> spheres = new ArrayList<>(count);
        for (SceneGenerator.Ball b : SceneGenerator.balls(count, 42)) {
            spheres.add(new Sphere(new Vector3f(b.x(), b.y(), b.z()), b.r(), new Color(b.red(), b.green(), b.blue())));
        }
        return new Scene(new Color(16, 18, 28), paperCamera(), spheres);
    }

    /** Makes and traces the rays of one image row, as the renderer does; returns a checksum. */
    static int traceRow(Tracer tracer, OrthographicCamera camera, int row) {
        int checksum = 0;
        for (int x = 0; x < WIDTH; x++) {
            Hit hit = tracer.nearestHit(camera.generateRay(x, row, WIDTH, HEIGHT));
            checksum += hit == null ? -1 : hit.index();
        }
        return checksum;
    }

    /**
     * Traces the band of 8 rows from {@code top} as the renderer does: square by square of
     * 8 × 8 pixels, through {@link Tracer#traceAll}.
     */
    static int traceBand(Tracer tracer, OrthographicCamera camera, int top, RayBundle rays, HitBuffer hits) {
        int checksum = 0;
        for (int left = 0; left < WIDTH; left += 8) {
            rays.fill(camera, left, top, left + 8, top + 8, WIDTH, HEIGHT);
            tracer.traceAll(rays, hits);
            checksum += hits.index(0) + hits.index(63);
        }
        return checksum;
    }

    static OrthographicCamera paperCamera() {
        return new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50);
    }
}
