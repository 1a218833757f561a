package rtd.accel;

import java.util.Arrays;
import rtd.geometry.IGeometry;
import rtd.geometry.Plane;
import rtd.geometry.TestObserver;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The objects without a box ({@link Bvh#unbounded}: planes), which every ray meets, with the
 * paper's intersection test on a ray given as numbers. A plane's point and normal are kept side
 * by side in one array, so that each ray's plane tests read six floats in a row rather than two
 * vectors of a plane object; the test is {@link Plane#hit}, the one the plane's own
 * {@link Plane#intersect} runs, so the answer is the same to the bit.
 */
final class UnboundedObjects {

    private final IGeometry[] objects;
    /** Each plane's Q and n, six floats; NaN for an object that is no plane. */
    private final float[] planes;

    UnboundedObjects(IGeometry[] objects) {
        this.objects = objects;
        this.planes = new float[6 * objects.length];
        for (int i = 0; i < objects.length; i++) {
            if (objects[i] instanceof Plane plane) {
                Vector3f q = plane.point();
                Vector3f n = plane.normal();
                float[] values = {q.x(), q.y(), q.z(), n.x(), n.y(), n.z()};
                System.arraycopy(values, 0, planes, 6 * i, 6);
            } else {
                Arrays.fill(planes, 6 * i, 6 * i + 6, Float.NaN);
            }
        }
    }

    /** How many there are. */
    int count() {
        return objects.length;
    }

    /** The t at which the ray {@code O + t·D} hits object {@code i}: negative or NaN for a miss. */
    float t(int i, float ox, float oy, float oz, float dx, float dy, float dz) {
        int at = 6 * i;
        if (planes[at] == planes[at]) { // a plane: its numbers are not NaN
            return Plane.hit(planes[at], planes[at + 1], planes[at + 2], planes[at + 3], planes[at + 4], planes[at + 5],
                    ox, oy, oz, dx, dy, dz, TestObserver.NONE);
        }
        return objects[i].intersect(new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz))).t();
    }
}
