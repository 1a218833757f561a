package rtd.cli;

import java.util.List;
import java.util.Optional;
import rtd.camera.ICamera;
import rtd.geometry.Hit;
import rtd.geometry.Plane;
import rtd.math.Ray;
import rtd.render.Tracer;
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

    /**
     * The warning for {@code scene} (its camera as rendered), named {@code name}, at {@code width ×
     * height}, if any: found by asking {@code tracer} what the camera's corner rays hit, so that
     * the look costs four rays and not a visit to each of a million objects.
     */
    static Optional<String> warning(String name, Scene scene, Tracer tracer, int width, int height) {
        Hit first = null;
        int inIt = 0;
        for (Ray ray : cornerRays(scene.camera(), width, height)) {
            Hit hit = tracer.nearestHit(ray);
            if (hit != null && hit.distance() == 0 && hit.object() instanceof Plane
                    && (first == null || hit.index() == first.index())) {
                first = first != null ? first : hit;
                inIt++;
            }
        }
        if (inIt < 3) { // one corner's ray may run along the plane, and meet it nowhere
            return Optional.empty();
        }
        Plane plane = (Plane) first.object();
        return Optional.of("rtd: warning: " + name + ": the camera stands in plane #" + (first.index() + 1) + " (through "
                + NothingInView.point(plane.point()) + ", normal " + NothingInView.point(plane.normal()) + "): every ray "
                + "that leaves it hits that plane at distance 0, so the picture shows that plane alone; move the camera or "
                + "the plane a little");
    }

    /**
     * The rays of the picture's four corners: they start in the plane if the camera stands in it,
     * and at most one runs along it (the middle one would run along a floor at the eye's height).
     */
    private static List<Ray> cornerRays(ICamera camera, int width, int height) {
        return List.of(camera.generateRay(0, 0, width, height), camera.generateRay(width - 1, 0, width, height),
                camera.generateRay(0, height - 1, width, height), camera.generateRay(width - 1, height - 1, width, height));
    }
}
