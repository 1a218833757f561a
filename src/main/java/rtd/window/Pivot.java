package rtd.window;

import java.util.List;
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
        List<BoundingBox> boxes = scene.objects().stream().map(IGeometry::bounds).filter(BoundingBox::isBounded)
                .toList();
        if (boxes.isEmpty()) {
            return centre.pointAt(10);
        }
        Vector3f min = boxes.stream().map(BoundingBox::min).reduce((a, b) -> each(a, b, Math::min)).orElseThrow();
        Vector3f max = boxes.stream().map(BoundingBox::max).reduce((a, b) -> each(a, b, Math::max)).orElseThrow();
        return new BoundingBox(min, max).centre();
    }

    /** {@code a} and {@code b} taken together coordinate by coordinate: the lowest or highest of each. */
    private static Vector3f each(Vector3f a, Vector3f b, BinaryOperator<Float> pick) {
        return new Vector3f(pick.apply(a.x(), b.x()), pick.apply(a.y(), b.y()), pick.apply(a.z(), b.z()));
    }
}
