package rtd.window;

import java.util.function.BinaryOperator;
import rtd.geometry.BoundingBox;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;

/**
 * The point the camera orbits around and pans at: what the centre pixel sees (its nearest hit, by the paper's depth
 * test), or where it sees nothing, the centre of the box around the objects that have one; with none, a point ahead on
 * the centre ray.
 */
final class Pivot {

    private Pivot() {
    }

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
                min = min == null ? box.min() : each(min, box.min(), Math::min);
                max = max == null ? box.max() : each(max, box.max(), Math::max);
            }
        }
        return min != null ? new BoundingBox(min, max).centre() : centre.pointAt(10);
    }

    /** {@code a} and {@code b} taken together coordinate by coordinate: the lowest or highest of each. */
    private static Vector3f each(Vector3f a, Vector3f b, BinaryOperator<Float> pick) {
        return new Vector3f(pick.apply(a.x(), b.x()), pick.apply(a.y(), b.y()), pick.apply(a.z(), b.z()));
    }
}
