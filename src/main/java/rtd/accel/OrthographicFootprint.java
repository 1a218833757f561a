package rtd.accel;

import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.math.Vector3f;

/**
 * The {@link ImageFootprint} of an object for the paper's orthographic camera: the shadow of
 * its grown box along the rays.
 *
 * <p>The camera's rays all run along one direction R from origins on a plane through its
 * position (Listing 4.1): pixel x's ray leaves {@code (x − w/2)/zoom} along the image axis u.
 * A ray that the test lets hit an object at t meets the object's box grown by its
 * {@link KnownShapes#rounding} at the distance {@code L = t·|R|}; its origin then lies where the
 * grown box's shadow along R falls on the plane. So the pixels are those of that shadow,
 * widened by what the rounding of the rays' own numbers can move them.
 */
final class OrthographicFootprint implements ImageFootprint {

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
    OrthographicFootprint(OrthographicCamera camera, int width, int height, double latestOffset) {
        Vector3f pos = camera.position();
        Vector3f dir = camera.direction();
        Vector3f u = camera.widthVector();
        Vector3f v = camera.heightVector();
        px = pos.x();
        py = pos.y();
        pz = pos.z();
        double length = Math.sqrt((double) dir.x() * dir.x() + (double) dir.y() * dir.y() + (double) dir.z() * dir.z());
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

    @Override
    public float put(float[] boxes, int at, float linear, float quadratic, int[] into, int to) {
        double hx = (boxes[at + 3] - (double) boxes[at]) / 2;
        double hy = (boxes[at + 4] - (double) boxes[at + 1]) / 2;
        double hz = (boxes[at + 5] - (double) boxes[at + 2]) / 2;
        double cx = (boxes[at] + (double) boxes[at + 3]) / 2 - px;
        double cy = (boxes[at + 1] + (double) boxes[at + 4]) / 2 - py;
        double cz = (boxes[at + 2] + (double) boxes[at + 5]) / 2 - pz;
        double middle = cx * rx + cy * ry + cz * rz;
        double depth = Math.abs(rx) * hx + Math.abs(ry) * hy + Math.abs(rz) * hz;
        double widest = linear + KnownShapes.ROUNDING_CONE;
        if (middle + depth + originError < 0) {
            return Float.NaN; // wholly behind the rays' origins: a hit lies no farther from the box than √3 growths
        }
        // a hit runs L ≤ farSide + √3·growth(L) ≤ farSide + √3·widest·L from the plane
        double reach = (middle + depth + originError) / (1 - Math.sqrt(3) * widest);
        double grow = ImageFootprint.growth(linear, quadratic, reach);
        double a = cx * ux + cy * uy + cz * uz;
        double b = cx * vx + cy * vy + cz * vz;
        double halfA = Math.abs(ux) * (hx + grow) + Math.abs(uy) * (hy + grow) + Math.abs(uz) * (hz + grow)
                + reach * driftU + originError;
        double halfB = Math.abs(vx) * (hx + grow) + Math.abs(vy) * (hy + grow) + Math.abs(vz) * (hz + grow)
                + reach * driftV + originError;
        if (!(widest * Math.sqrt(3) < 0.5 && Double.isFinite(halfA + halfB + a + b))) {
            ImageFootprint.whole(width, height, into, to);
            return Float.NEGATIVE_INFINITY;
        }
        boolean seen = ImageFootprint.range(halfWidth + zoom * (a - halfA), halfWidth + zoom * (a + halfA), width,
                latestOffset, into, to)
                && ImageFootprint.range(halfHeight + zoom * (b - halfB), halfHeight + zoom * (b + halfB), height,
                        latestOffset, into, to + 1);
        // the hit P = O + t·R lies in the grown box, so |P − O| ≥ (P − O)·R/|R|: its near side less the origin's error
        return seen ? ImageFootprint.below(middle - depth - Math.sqrt(3) * grow - originError) : Float.NaN;
    }
}
