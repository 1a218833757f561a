package rtd.window;

import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;

/**
 * The point the camera orbits around and pans at: what the centre pixel sees (its nearest hit, by the paper's
 * depth test), or where it sees nothing, the middle of the centres of the objects' boxes; with no box, a point
 * ahead on the centre ray.
 */
final class Pivot {

    private Pivot() {
    }

    /** The pivot of {@code scene}'s {@code width × height} picture. */
    static Vector3f of(Scene scene, int width, int height) {
        Ray centre = scene.camera().generateRay(width / 2, height / 2, width, height);
        Hit hit = scene.nearestHit(centre);
        if (hit != null) {
            return hit.point();
        }
        Vector3f sum = Vector3f.ZERO;
        int bounded = 0;
        for (IGeometry object : scene.objects()) {
            if (object.bounds().isBounded()) {
                sum = sum.add(object.bounds().centre());
                bounded++;
            }
        }
        return bounded > 0 ? sum.divide(bounded) : centre.pointAt(10);
    }
}
