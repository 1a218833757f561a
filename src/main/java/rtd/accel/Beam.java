package rtd.accel;

import rtd.camera.OrthographicCamera;
import rtd.render.RayBundle;

/**
 * The rays of a square of pixels, bounded: their origins lie in the box from {@code lowest} to
 * {@code highest}, and their directions differ from the middle direction {@code (dx, dy, dz)}
 * by at most {@code spread} along each axis. Not in the paper: the {@link BeamTracer} walks the
 * tree once for all of them. The orthographic camera's rays (section 3.2.1) all run along one
 * direction, so their spread is 0; the perspective camera's all start at the eye, so their
 * origins' box is a point, and a square's directions differ by a few thousandths. One per
 * tracer, aimed anew at each square, so that finding a square's beam makes no garbage.
 */
final class Beam {

    /**
     * The widest spread of directions, as a share of the middle direction's length, for which
     * one walk pays: an 8 × 8 square of a perspective camera of 60° at 1920 pixels spreads by
     * about 0.3 %; rays that spread more (unrelated rays put in one bundle) go one by one.
     */
    static final float WIDEST_SPREAD = 0.01f;
    /** Margin on the spread and lengths for rounding: far more than the few units in the last place involved. */
    private static final float ROUNDING = 1e-6f;

    /** The smallest x, y and z of any origin. */
    final float[] lowest = new float[3];
    /** The largest x, y and z of any origin. */
    final float[] highest = new float[3];
    /** Per axis, how far any ray's direction is from the middle one; 0 for parallel rays. */
    final float[] spread = new float[3];
    float dx;
    float dy;
    float dz;
    /** The shortest and the longest direction |D| of any ray. */
    float shortest;
    float longest;
    private final float[] lowestDirection = new float[3];
    private final float[] highestDirection = new float[3];
    /** A corner ray's numbers, origin then direction; kept so that aiming makes no garbage. */
    private final float[] corner = new float[6];

    /**
     * Becomes the beam of the bundle's rays; false if an origin or direction is not finite (then
     * float cannot hold the beam's size), or the directions spread too wide for a beam.
     *
     * <p>For a square of the orthographic camera the four corner rays suffice, and the others
     * are not made. Why the corners hold every origin, even with rounding: in
     * {@link OrthographicCamera#putRay} (the numbers of its {@code generateRay}, to the bit) each
     * coordinate of the origin is made from the pixel's x by a product, a quotient by
     * {@code zoom > 0} and two sums, and from y likewise. Each of these is monotonic in its input, and rounding to nearest keeps it
     * monotonic, so each coordinate only grows (or only shrinks) as x grows, and as y grows: its
     * smallest and largest values over the square lie at corners. Other cameras' rays are all
     * made and looked at.
     */
    boolean aimAt(RayBundle bundle) {
        if (bundle.count() == 0) {
            return false;
        }
        if (bundle.camera() instanceof OrthographicCamera) {
            for (int k = 0; k < 4; k++) {
                bundle.putCorner(k, corner);
                add(k == 0, corner[0], corner[1], corner[2], corner[3], corner[4], corner[5]);
            }
        } else {
            bundle.make();
            for (int i = 0; i < bundle.count(); i++) {
                add(i == 0, bundle.originX(i), bundle.originY(i), bundle.originZ(i),
                        bundle.directionX(i), bundle.directionY(i), bundle.directionZ(i));
            }
        }
        return settle();
    }

    /** Grows the bounds to hold a ray's origin and direction. */
    private void add(boolean first, float ox, float oy, float oz, float rx, float ry, float rz) {
        grow(lowest, highest, 0, ox, first);
        grow(lowest, highest, 1, oy, first);
        grow(lowest, highest, 2, oz, first);
        grow(lowestDirection, highestDirection, 0, rx, first);
        grow(lowestDirection, highestDirection, 1, ry, first);
        grow(lowestDirection, highestDirection, 2, rz, first);
        float length = (float) Math.sqrt((rx * rx) + (ry * ry) + (rz * rz)); // as NearestHit sums it
        shortest = first ? length : Math.min(shortest, length);
        longest = first ? length : Math.max(longest, length);
    }

    private static void grow(float[] low, float[] high, int k, float value, boolean first) {
        low[k] = first ? value : Math.min(low[k], value);
        high[k] = first ? value : Math.max(high[k], value);
    }

    /**
     * The middle direction and the spread from the bounds; false if a number is not finite or
     * the spread is too wide. Directions that are the same to the bit spread by exactly 0.
     */
    private boolean settle() {
        float widest = 0;
        for (int k = 0; k < 3; k++) {
            float low = lowestDirection[k];
            float high = highestDirection[k];
            boolean same = Float.floatToRawIntBits(low) == Float.floatToRawIntBits(high);
            spread[k] = same ? 0 : (high - low) / 2 + ROUNDING * (Math.abs(low) + Math.abs(high));
            widest = Math.max(widest, spread[k]);
            if (!Float.isFinite(lowest[k]) || !Float.isFinite(highest[k]) || !Float.isFinite(low)
                    || !Float.isFinite(high) || !Float.isFinite(spread[k])) {
                return false;
            }
        }
        dx = lowestDirection[0] == highestDirection[0] ? lowestDirection[0] : (lowestDirection[0] + highestDirection[0]) / 2;
        dy = lowestDirection[1] == highestDirection[1] ? lowestDirection[1] : (lowestDirection[1] + highestDirection[1]) / 2;
        dz = lowestDirection[2] == highestDirection[2] ? lowestDirection[2] : (lowestDirection[2] + highestDirection[2]) / 2;
        shortest *= 1 - ROUNDING;
        longest *= 1 + ROUNDING;
        return widest <= WIDEST_SPREAD * shortest;
    }
}
