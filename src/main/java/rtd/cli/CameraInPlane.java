package rtd.cli;

import java.util.List;
import java.util.Optional;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.geometry.Plane;
import rtd.math.Ray;
import rtd.scene.Scene;

/**
 * The warning for a camera that stands exactly in a plane (a floor at the eye's height): every
 * ray that leaves it hits the plane at {@code t = 0}, which counts as a hit ({@code t ≥ 0}, as
 * the paper's sphere test counts it), and at distance 0 it wins every depth test. The picture is
 * then that plane alone, which a user would otherwise take for a bug.
 */
final class CameraInPlane {

    private CameraInPlane() {
    }

    /** The warning for {@code scene} (its camera as rendered), named {@code name}, at {@code width × height}; if any. */
    static Optional<String> warning(String name, Scene scene, int width, int height) {
        List<Ray> rays = sampleRays(scene.camera(), width, height);
        List<IGeometry> objects = scene.objects();
        for (int i = 0; i < objects.size(); i++) {
            if (objects.get(i) instanceof Plane plane && startInIt(plane, rays)) {
                return Optional.of("rtd: warning: " + name + ": the camera stands in plane #" + (i + 1) + " (through "
                        + NothingInView.point(plane.point()) + ", normal " + NothingInView.point(plane.normal()) + "): every ray that leaves it hits that plane "
                        + "at distance 0, so the picture shows that plane alone; move the camera or the plane a little");
            }
        }
        return Optional.empty();
    }

    /** The rays of the picture's corners and middle: they start in the plane if the camera stands in it. */
    private static List<Ray> sampleRays(ICamera camera, int width, int height) {
        return List.of(camera.generateRay(0, 0, width, height), camera.generateRay(width - 1, 0, width, height),
                camera.generateRay(0, height - 1, width, height),
                camera.generateRay(width - 1, height - 1, width, height),
                camera.generateRay(width / 2, height / 2, width, height));
    }

    /** Whether most of the rays (those not parallel to the plane) hit it where they start. */
    private static boolean startInIt(Plane plane, List<Ray> rays) {
        int atTheStart = 0;
        for (Ray ray : rays) {
            Intersection hit = plane.intersect(ray);
            atTheStart += hit.happened() && hit.t() == 0 ? 1 : 0;
        }
        return atTheStart >= 3;
    }
}
