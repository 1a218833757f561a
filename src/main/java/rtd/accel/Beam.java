package rtd.accel;

import rtd.camera.OrthographicCamera;
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
    /** One ray's numbers, origin then direction, as the bundle gives them; kept so that aiming makes no garbage. */
    private final float[] ray = new float[6];

    /**
     * Becomes the beam of the bundle's rays; false if they are not all parallel or an origin is
     * not finite (then float cannot hold the beam's size).
     *
     * <p>For a square of the orthographic camera the four corner rays suffice, and the others
     * are not made. Why the corners hold every origin, even with rounding: in
     * {@link OrthographicCamera#putRay} (the numbers of its {@code generateRay}, to the bit)
     * each coordinate of the origin is made from the pixel's x by a product, a quotient by
     * {@code zoom > 0} and two sums, and from y likewise. Each of these is monotonic in its
     * input, and rounding to nearest keeps it monotonic, so each coordinate only grows (or only
     * shrinks) as x grows, and as y grows: its smallest and largest values over the square lie at
     * corners.
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
            if (corners) {
                bundle.putCorner(i, ray);
            } else {
                ray[0] = bundle.originX(i);
                ray[1] = bundle.originY(i);
                ray[2] = bundle.originZ(i);
                ray[3] = bundle.directionX(i);
                ray[4] = bundle.directionY(i);
                ray[5] = bundle.directionZ(i);
            }
            if (!add(i == 0)) {
                return false;
            }
        }
        return true;
    }

    /** Grows the beam to hold {@link #ray}'s origin; false if the ray is not parallel to the beam or not finite. */
    private boolean add(boolean first) {
        if (!Float.isFinite(ray[0]) || !Float.isFinite(ray[1]) || !Float.isFinite(ray[2])) {
            return false;
        }
        if (first) {
            dx = ray[3];
            dy = ray[4];
            dz = ray[5];
        } else if (!sameBits(ray[3], dx) || !sameBits(ray[4], dy) || !sameBits(ray[5], dz)) {
            return false;
        }
        grow(0, ray[0], first);
        grow(1, ray[1], first);
        grow(2, ray[2], first);
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
