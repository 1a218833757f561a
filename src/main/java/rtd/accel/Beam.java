package rtd.accel;

import rtd.camera.OrthographicCamera;
import rtd.math.Ray;
import rtd.render.RayBundle;

/**
 * Rays that all run along one direction {@code (dx, dy, dz)} from origins inside the box from
 * {@code lowest} to {@code highest}: the rays of a square of pixels of a parallel projection
 * such as the paper's orthographic camera (section 3.2.1). Not in the paper: the
 * {@link BeamTracer} walks the tree once for all of them. One per tracer, aimed anew at each
 * square, so that finding a square's beam makes no garbage.
 */
final class Beam {

    /** The smallest x, y and z of any origin. */
    final float[] lowest = new float[3];
    /** The largest x, y and z of any origin. */
    final float[] highest = new float[3];
    float dx;
    float dy;
    float dz;

    /**
     * Becomes the beam of the bundle's rays; false if they are not all parallel or an origin is
     * not finite (then float cannot hold the beam's size).
     *
     * <p>For a square of the orthographic camera the four corner rays suffice, and the others
     * are not made. Why the corners hold every origin, even with rounding: in
     * {@link OrthographicCamera#generateRay(int, int, int, int)} each coordinate of the origin
     * is made from the pixel's x by a product, a quotient by {@code zoom > 0} and two sums, and
     * from y likewise. Each of these is monotonic in its input, and rounding to nearest keeps it
     * monotonic, so each coordinate only grows (or only shrinks) as x grows, and as y grows: its
     * smallest and largest values over the square lie at corners.
     */
    boolean aimAt(RayBundle bundle) {
        if (bundle.count() == 0) {
            return false;
        }
        boolean corners = bundle.camera() instanceof OrthographicCamera;
        if (!corners) {
            bundle.make();
        }
        int rays = corners ? 4 : bundle.count();
        for (int i = 0; i < rays; i++) {
            Ray ray = corners ? bundle.corner(i) : bundle.ray(i);
            if (!add(i == 0, ray)) {
                return false;
            }
        }
        return true;
    }

    /** Grows the beam to hold {@code ray}'s origin; false if the ray is not parallel to the beam or not finite. */
    private boolean add(boolean first, Ray ray) {
        if (!ray.origin().isFinite()) {
            return false;
        }
        if (first) {
            dx = ray.direction().x();
            dy = ray.direction().y();
            dz = ray.direction().z();
        } else if (!sameBits(ray.direction().x(), dx) || !sameBits(ray.direction().y(), dy)
                || !sameBits(ray.direction().z(), dz)) {
            return false;
        }
        grow(0, ray.origin().x(), first);
        grow(1, ray.origin().y(), first);
        grow(2, ray.origin().z(), first);
        return true;
    }

    private void grow(int k, float value, boolean first) {
        lowest[k] = first ? value : Math.min(lowest[k], value);
        highest[k] = first ? value : Math.max(highest[k], value);
    }

    private static boolean sameBits(float a, float b) {
        return Float.floatToRawIntBits(a) == Float.floatToRawIntBits(b);
    }
}
