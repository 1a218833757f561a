package rtd.window;

import rtd.geometry.BoundingBox;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;

/**
 * The point the camera orbits around and pans at: what the centre pixel sees (its nearest hit, by the paper's
 * depth test), or where it sees nothing, the centre of the box around the objects that have one; with none, a
 * point ahead on the centre ray.
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
        Vector3f min = null;
        Vector3f max = null;
        for (IGeometry object : scene.objects()) {
            BoundingBox box = object.bounds();
            if (box.isBounded()) {
                min = min == null ? box.min() : lowest(min, box.min());
                max = max == null ? box.max() : highest(max, box.max());
            }
        }
        return min != null ? new BoundingBox(min, max).centre() : centre.pointAt(10);
    }

    private static Vector3f lowest(Vector3f a, Vector3f b) {
        return new Vector3f(Math.min(a.x(), b.x()), Math.min(a.y(), b.y()), Math.min(a.z(), b.z()));
    }

    private static Vector3f highest(Vector3f a, Vector3f b) {
        return new Vector3f(Math.max(a.x(), b.x()), Math.max(a.y(), b.y()), Math.max(a.z(), b.z()));
    }
}
