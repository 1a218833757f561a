package rtd.accel;

import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.math.Vector3f;

/**
 * Where on the image an orthographic camera may see an object: the rectangle of pixels whose
 * rays {@link IGeometry#intersect} may report a hit on it, rounding included. Not in the paper;
 * the {@link ViewGrid} sorts the objects into the image's cells by it.
 *
 * <p>The camera's rays all run along one direction R from origins on a plane through its
 * position (Listing 4.1): pixel x's ray leaves {@code (x − w/2)/zoom} along the image axis u.
 * A ray that the test lets hit an object at t meets the object's box grown by its
 * {@link IGeometry#rounding} at the distance {@code L = t·|R|} ({@link IGeometry#bounds}); its
 * origin then lies where the grown box's shadow along R falls on the plane. So the pixels are
 * those of that shadow, widened by what the rounding of the rays' own numbers can move them.
 * Everything is worked out in double from the camera's float numbers, with margins far above
 * double rounding, and a pixel whose ray might hit is always kept: the grid may test an object
 * in vain, but never leave out one the paper's loop would find.
 */
final class ImageFootprint {

    /**
     * How far, relative to the numbers it is made of, a ray's float origin may lie from where
     * exact arithmetic puts it: four roundings of the camera's sums, and the image axes being
     * unit and square to R only to float precision, with room to spare.
     */
    private static final double ORIGIN_ERROR = 1e-6;

    private final double px;
    private final double py;
    private final double pz;
    private final double rx;
    private final double ry;
    private final double rz;
    /** |R|, to turn distances along R into t. */
    private final double length;
    private final double ux;
    private final double uy;
    private final double uz;
    private final double vx;
    private final double vy;
    private final double vz;
    private final double zoom;
    private final int width;
    private final int height;
    private final int halfWidth;
    private final int halfHeight;
    /** The largest offset of a ray within its pixel: 0 for the corner, less than 1 for a sample. */
    private final double latestOffset;
    /** How far a ray's origin may lie from the exact one, in world units. */
    private final double originError;
    /** How far a ray drifts along u, and along v, per unit it runs: u and v are square to R only to float precision. */
    private final double driftU;
    private final double driftV;

    /**
     * The footprints on a {@code width × height} image of {@code camera}, for rays through the
     * pixels' corners and through points up to {@code latestOffset} (less than 1) into them.
     */
    ImageFootprint(OrthographicCamera camera, int width, int height, double latestOffset) {
        Vector3f pos = camera.position();
        Vector3f dir = camera.direction();
        Vector3f u = camera.widthVector();
        Vector3f v = camera.heightVector();
        px = pos.x();
        py = pos.y();
        pz = pos.z();
        length = Math.sqrt((double) dir.x() * dir.x() + (double) dir.y() * dir.y() + (double) dir.z() * dir.z());
        rx = dir.x() / length;
        ry = dir.y() / length;
        rz = dir.z() / length;
        ux = u.x();
        uy = u.y();
        uz = u.z();
        vx = v.x();
        vy = v.y();
        vz = v.z();
        zoom = camera.zoom();
        this.width = width;
        this.height = height;
        halfWidth = width / 2; // as Listing 4.1 divides
        halfHeight = height / 2;
        this.latestOffset = latestOffset;
        originError = ORIGIN_ERROR * (Math.abs(px) + Math.abs(py) + Math.abs(pz) + (width + height + 2) / Math.abs(zoom));
        driftU = Math.abs(rx * ux + ry * uy + rz * uz);
        driftV = Math.abs(rx * vx + ry * vy + rz * vz);
    }

    /**
     * The pixels {@code [x0, x1] × [y0, y1]} (inclusive, within the image) whose rays may hit
     * the object of box {@code boxes[at .. at+5]} and rounding {@code linear}, {@code quadratic},
     * into {@code into[to .. to+3]} as x0, y0, x1, y1; and the answer: a t before which none of
     * them hits it. NaN, with nothing written, if no ray of the picture can hit it. A box the
     * numbers cannot place (not finite, or a rounding too wide to bound) covers the whole image,
     * from t = −∞.
     */
    float put(float[] boxes, int at, float linear, float quadratic, int[] into, int to) {
        double hx = (boxes[at + 3] - (double) boxes[at]) / 2;
        double hy = (boxes[at + 4] - (double) boxes[at + 1]) / 2;
        double hz = (boxes[at + 5] - (double) boxes[at + 2]) / 2;
        double cx = (boxes[at] + (double) boxes[at + 3]) / 2 - px;
        double cy = (boxes[at + 1] + (double) boxes[at + 4]) / 2 - py;
        double cz = (boxes[at + 2] + (double) boxes[at + 5]) / 2 - pz;
        double middle = cx * rx + cy * ry + cz * rz;
        double depth = Math.abs(rx) * hx + Math.abs(ry) * hy + Math.abs(rz) * hz;
        double widest = linear + IGeometry.ROUNDING_CONE;
        if (middle + depth + originError < 0) {
            return Float.NaN; // wholly behind the rays' origins: a hit lies no farther from the box than √3 growths
        }
        // a hit runs L ≤ farSide + √3·growth(L) ≤ farSide + √3·widest·L from the plane
        double reach = (middle + depth + originError) / (1 - Math.sqrt(3) * widest);
        double grow = linear * reach + Math.min(IGeometry.ROUNDING_CONE * reach, quadratic * reach * reach);
        double a = cx * ux + cy * uy + cz * uz;
        double b = cx * vx + cy * vy + cz * vz;
        double halfA = Math.abs(ux) * (hx + grow) + Math.abs(uy) * (hy + grow) + Math.abs(uz) * (hz + grow)
                + reach * driftU + originError;
        double halfB = Math.abs(vx) * (hx + grow) + Math.abs(vy) * (hy + grow) + Math.abs(vz) * (hz + grow)
                + reach * driftV + originError;
        if (!(widest * Math.sqrt(3) < 0.5 && Double.isFinite(halfA + halfB + a + b))) {
            whole(into, to);
            return Float.NEGATIVE_INFINITY;
        }
        boolean seen = range(halfWidth + zoom * (a - halfA), halfWidth + zoom * (a + halfA), width, into, to)
                && range(halfHeight + zoom * (b - halfB), halfHeight + zoom * (b + halfB), height, into, to + 1);
        // the hit P = O + t·R lies in the grown box, so t·|R| = (P − O)·R/|R| is at least its near side less the origin's error
        double nearest = (middle - depth - Math.sqrt(3) * grow - originError) / length;
        float before = Math.nextDown((float) (nearest - 1e-6 * Math.abs(nearest)));
        return !seen ? Float.NaN : before == before ? before : Float.NEGATIVE_INFINITY;
    }

    /**
     * The pixels p of {@code [0, size)} with a ray at {@code p + offset} between {@code one} and {@code other}
     * for some offset {@code 0 ≤ offset ≤ latestOffset}, as first and last at {@code into[to]}
     * and {@code into[to + 2]}; false if there are none.
     */
    private boolean range(double one, double other, int size, int[] into, int to) {
        double first = Math.max(0, Math.ceil(Math.min(one, other) - latestOffset)); // a negative zoom swaps them
        double last = Math.min(size - 1, Math.floor(Math.max(one, other)));
        if (!(first <= last)) {
            return false;
        }
        into[to] = (int) first;
        into[to + 2] = (int) last;
        return true;
    }

    private void whole(int[] into, int to) {
        into[to] = 0;
        into[to + 1] = 0;
        into[to + 2] = width - 1;
        into[to + 3] = height - 1;
    }
}
