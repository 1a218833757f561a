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

    /**
     * The most objects looked through for planes: a student's scene, in a millisecond or two. A
     * million objects, scattered in memory, take 15–25 ms to visit, and asking a tracer about a
     * ray that is not on its grid tests every one of them (40 ms for four rays, measured).
     */
    private static final int MOST_LOOKED_AT = 100_000;

    private CameraInPlane() {
    }

    /** The warning for {@code scene} (its camera as rendered), named {@code name}, at {@code width × height}; if any. */
    static Optional<String> warning(String name, Scene scene, int width, int height) {
        List<IGeometry> objects = scene.objects();
        if (objects.size() > MOST_LOOKED_AT) {
            return Optional.empty();
        }
        List<Ray> rays = cornerRays(scene.camera(), width, height);
        for (int i = 0; i < objects.size(); i++) {
            if (objects.get(i) instanceof Plane plane && startInIt(plane, rays)) {
                return Optional.of("rtd: warning: " + name + ": the camera stands in plane #" + (i + 1) + " (through "
                        + NothingInView.point(plane.point()) + ", normal " + NothingInView.point(plane.normal()) + "): every "
                        + "ray that leaves it hits that plane at distance 0, so the picture shows that plane alone; move the "
                        + "camera or the plane a little");
            }
        }
        return Optional.empty();
    }

    /**
     * The rays of the picture's four corners: they start in the plane if the camera stands in it,
     * and at most one runs along it (the middle one would run along a floor at the eye's height).
     */
    private static List<Ray> cornerRays(ICamera camera, int width, int height) {
        return List.of(camera.generateRay(0, 0, width, height), camera.generateRay(width - 1, 0, width, height),
                camera.generateRay(0, height - 1, width, height), camera.generateRay(width - 1, height - 1, width, height));
    }

    /** Whether at least three of the corner rays hit the plane where they start (one may run along it). */
    private static boolean startInIt(Plane plane, List<Ray> rays) {
        int atTheStart = 0;
        for (Ray ray : rays) {
            Intersection hit = plane.intersect(ray);
            atTheStart += hit.happened() && hit.t() == 0 ? 1 : 0;
        }
        return atTheStart >= 3;
    }
}
