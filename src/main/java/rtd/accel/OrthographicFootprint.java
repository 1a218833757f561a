package rtd.accel;

import rtd.camera.OrthographicCamera;
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

    private final double[] position;
    /** The rays' direction R, of unit length. */
    private final double[] along;
    private final double[] u;
    private final double[] v;
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

    /** As {@link ImageFootprint#of} makes it. */
    OrthographicFootprint(OrthographicCamera camera, int width, int height, double latestOffset) {
        Vector3f dir = camera.direction();
        position = ImageFootprint.numbers(camera.position());
        double length = Math.sqrt((double) dir.x() * dir.x() + (double) dir.y() * dir.y() + (double) dir.z() * dir.z());
        along = new double[] {dir.x() / length, dir.y() / length, dir.z() / length};
        u = ImageFootprint.numbers(camera.widthVector());
        v = ImageFootprint.numbers(camera.heightVector());
        zoom = camera.zoom();
        this.width = width;
        this.height = height;
        halfWidth = width / 2; // as Listing 4.1 divides
        halfHeight = height / 2;
        this.latestOffset = latestOffset;
        originError = ORIGIN_ERROR * (Math.abs(position[0]) + Math.abs(position[1]) + Math.abs(position[2])
                + (width + height + 2) / Math.abs(zoom));
        driftU = Math.abs(ImageFootprint.dot(along, u));
        driftV = Math.abs(ImageFootprint.dot(along, v));
    }

    @Override
    public float put(float[] boxes, int at, float linear, float quadratic, int[] into, int to) {
        double hx = (boxes[at + 3] - (double) boxes[at]) / 2;
        double hy = (boxes[at + 4] - (double) boxes[at + 1]) / 2;
        double hz = (boxes[at + 5] - (double) boxes[at + 2]) / 2;
        double[] middle = {(boxes[at] + (double) boxes[at + 3]) / 2 - position[0],
                (boxes[at + 1] + (double) boxes[at + 4]) / 2 - position[1],
                (boxes[at + 2] + (double) boxes[at + 5]) / 2 - position[2]};
        double ahead = ImageFootprint.dot(middle, along);
        double depth = Math.abs(along[0]) * hx + Math.abs(along[1]) * hy + Math.abs(along[2]) * hz;
        double widest = linear + KnownShapes.ROUNDING_CONE;
        if (ahead + depth + originError < 0) {
            return Float.NaN; // wholly behind the rays' origins: a hit lies no farther from the box than √3 growths
        }
        // a hit runs L ≤ farSide + √3·growth(L) ≤ farSide + √3·widest·L from the plane
        double reach = (ahead + depth + originError) / (1 - Math.sqrt(3) * widest);
        double grow = ImageFootprint.growth(linear, quadratic, reach);
        double a = ImageFootprint.dot(middle, u);
        double b = ImageFootprint.dot(middle, v);
        double halfA = Math.abs(u[0]) * (hx + grow) + Math.abs(u[1]) * (hy + grow) + Math.abs(u[2]) * (hz + grow)
                + reach * driftU + originError;
        double halfB = Math.abs(v[0]) * (hx + grow) + Math.abs(v[1]) * (hy + grow) + Math.abs(v[2]) * (hz + grow)
                + reach * driftV + originError;
        if (!(widest * Math.sqrt(3) < 0.5 && Double.isFinite(halfA + halfB + a + b))) {
            return ImageFootprint.whole(width, height, into, to);
        }
        // the hit P = O + t·R lies in the grown box, so |P − O| ≥ (P − O)·R/|R|: its near side less the origin's error
        return ImageFootprint.rectangle(halfWidth + zoom * (a - halfA), halfWidth + zoom * (a + halfA),
                halfHeight + zoom * (b - halfB), halfHeight + zoom * (b + halfB), width, height, latestOffset,
                ahead - depth - Math.sqrt(3) * grow - originError, into, to);
    }
}
