package rtd.accel;

import java.util.List;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.IGeometry;
import rtd.math.Vector3f;

/**
 * Where on the image a camera may see an object: the rectangle of pixels whose rays
 * {@link IGeometry#intersect} may report a hit on it, rounding included, and how near to a
 * ray's origin such a hit can lie. Not in the paper; the {@link ViewGrid} sorts the objects into
 * the image's cells by it, and each cell's objects by that distance.
 *
 * <p>A ray that the test lets hit an object meets the object's box grown by its
 * {@link KnownShapes#rounding} at the distance {@code L} the ray has run ({@link IGeometry#bounds}).
 * So an object's pixels are those whose rays pass through the grown box: its shadow along the
 * rays of the orthographic camera ({@link OrthographicFootprint}), its picture through the
 * perspective camera's eye ({@link PerspectiveFootprint}), widened by what the rounding of the
 * rays' own numbers can move them. Both work in double from the camera's float numbers, with
 * margins far above double rounding: the grid may test an object in vain, but never leaves out
 * one that the paper's loop would find. The {@link LightGrids} use the same idea seen from a light
 * ({@link PointFootprint}).
 */
interface ImageFootprint {

    /**
     * The pixels {@code [x0, x1] × [y0, y1]} (inclusive, within the image) whose rays may hit the object of box
     * {@code boxes[at .. at+5]} and rounding {@code linear}, {@code quadratic}, into {@code into[to .. to+3]} as x0,
     * y0, x1, y1; and the answer: a distance from the ray's origin before which none of them hits it (for a
     * {@link PointFootprint}, from its point X); NaN if no ray of the picture can hit it (what it wrote into
     * {@code into} then means nothing); −∞ where the numbers cannot bound it (then all pixels).
     */
    float put(float[] boxes, int at, float linear, float quadratic, int[] into, int to);

    /**
     * {@link #put} for {@code object}: its footprint into {@code into[at ..]} (x0 > x1 if no ray
     * sees it) and its nearest distance, NaN if no ray sees it or it has no finite box;
     * {@code box} is room for its bounds, which it holds afterwards.
     */
    default float putObject(IGeometry object, float[] box, int[] into, int at) {
        KnownShapes.putBox(object, box, 0);
        Rounding rounding = roundingOf(object, box);
        float nearest = isFinite(box) ? put(box, 0, rounding.linear(), rounding.quadratic(), into, at) : Float.NaN;
        if (nearest != nearest) {
            into[at] = 1; // x0 > x1: no pixel
            into[at + 2] = 0;
        }
        return nearest;
    }

    /**
     * The {@link Rounding} of the camera's rays for {@code object}, whose bounds are
     * {@code box[0 .. 5]}: {@link KnownShapes#rounding} unless the camera's rays have less
     * ({@link PerspectiveFootprint}).
     */
    default Rounding roundingOf(IGeometry object, float[] box) {
        return KnownShapes.rounding(object);
    }

    /**
     * The footprints of a sample of {@code objects} spread evenly over the file: every
     * {@code step}-th from the first, {@code step} chosen so that there are at most about
     * {@code most}, 4 ints each as {@link #putObject} writes them.
     */
    default int[] ofSample(List<IGeometry> objects, int most) {
        int count = objects.size();
        int step = Math.max(1, count / most);
        int[] sample = new int[4 * ((count + step - 1) / step)];
        float[] box = new float[6];
        for (int f = 0, at = 0; f < count; f += step, at += 4) {
            putObject(objects.get(f), box, sample, at);
        }
        return sample;
    }

    /** Whether all six numbers of a box are finite. */
    static boolean isFinite(float[] box) {
        for (float value : box) {
            if (!Float.isFinite(value)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The footprints on a {@code width × height} image of {@code camera}, for rays through the
     * pixels' corners and through points up to {@code latestOffset} (less than 1) into them.
     */
    static ImageFootprint of(ICamera camera, int width, int height, double latestOffset) {
        if (camera instanceof OrthographicCamera orthographic) {
            return new OrthographicFootprint(orthographic, width, height, latestOffset);
        }
        return new PerspectiveFootprint((PerspectiveCamera) camera, width, height, latestOffset);
    }

    /** Whether {@link #of} has a footprint for this camera's rays. */
    static boolean fits(ICamera camera) {
        return camera instanceof OrthographicCamera || camera instanceof PerspectiveCamera;
    }

    /**
     * The pixels p of a {@code width × height} image with a ray at {@code p + offset} between {@code left} and
     * {@code right}, and between {@code top} and {@code bottom}, for some offset {@code 0 ≤ offset ≤ latestOffset},
     * into {@code into[to ..]} as {@link #put} writes them; and its answer: a distance below {@code nearest}, by more
     * than rounding its double computation could have moved it (−∞ for NaN), or NaN if there are no such pixels.
     */
    static float rectangle(double left, double right, double top, double bottom, int width, int height,
            double latestOffset, double nearest, int[] into, int to) {
        if (!(range(left, right, width, latestOffset, into, to) && range(top, bottom, height, latestOffset, into,
                to + 1))) {
            return Float.NaN;
        }
        float below = Math.nextDown((float) (nearest - 1e-6 * Math.abs(nearest)));
        return below == below ? below : Float.NEGATIVE_INFINITY;
    }

    private static boolean range(double one, double other, int size, double latestOffset, int[] into, int to) {
        double first = Math.max(0, Math.ceil(Math.min(one, other) - latestOffset));
        double last = Math.min(size - 1, Math.floor(Math.max(one, other)));
        if (!(first <= last)) { // also for NaN
            return false;
        }
        into[to] = (int) first;
        into[to + 2] = (int) last;
        return true;
    }

    /** All pixels of a {@code width × height} image, for an object the numbers cannot bound; answers −∞. */
    static float whole(int width, int height, int[] into, int to) {
        into[to] = 0;
        into[to + 1] = 0;
        into[to + 2] = width - 1;
        into[to + 3] = height - 1;
        return Float.NEGATIVE_INFINITY;
    }

    /**
     * How far a hit may stray from the box of an object of rounding {@code linear},
     * {@code quadratic}, at distance {@code run} from the ray's origin: {@link IGeometry#bounds}'
     * {@code linear·L + min(ROUNDING_CONE·L, quadratic·L²)}, in double.
     */
    static double growth(double linear, double quadratic, double run) {
        return linear * run + Math.min(KnownShapes.ROUNDING_CONE * run, quadratic * run * run);
    }

    /** How far 0 lies from the box {@code [x0, x1] × [y0, y1] × [z0, z1]}. */
    static double distance(double x0, double y0, double z0, double x1, double y1, double z1) {
        return Math.sqrt(outside(x0, x1) + outside(y0, y1) + outside(z0, z1));
    }

    /** How far 0 lies from the farthest corner of the box {@code [x0, x1] × [y0, y1] × [z0, z1]}. */
    static double farthest(double x0, double y0, double z0, double x1, double y1, double z1) {
        return Math.sqrt(farther(x0, x1) + farther(y0, y1) + farther(z0, z1));
    }

    private static double farther(double low, double high) {
        double far = Math.max(Math.abs(low), Math.abs(high));
        return far * far;
    }

    /** The least dot product of a point of the box {@code [x0, x1] × [y0, y1] × [z0, z1]} with {@code axis}. */
    static double leastAlong(double x0, double y0, double z0, double x1, double y1, double z1, double[] axis) {
        return least(x0, x1, axis[0]) + least(y0, y1, axis[1]) + least(z0, z1, axis[2]);
    }

    /** The largest dot product of a point of the box {@code [x0, x1] × [y0, y1] × [z0, z1]} with {@code axis}. */
    static double mostAlong(double x0, double y0, double z0, double x1, double y1, double z1, double[] axis) {
        return most(x0, x1, axis[0]) + most(y0, y1, axis[1]) + most(z0, z1, axis[2]);
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /** A vector's numbers, in double. */
    static double[] numbers(Vector3f vector) {
        return new double[] {vector.x(), vector.y(), vector.z()};
    }

    /** The square of how far 0 lies outside {@code [low, high]}. */
    private static double outside(double low, double high) {
        double outside = Math.max(0, Math.max(low, -high));
        return outside * outside;
    }

    private static double least(double low, double high, double factor) {
        return Math.min(low * factor, high * factor);
    }

    private static double most(double low, double high, double factor) {
        return Math.max(low * factor, high * factor);
    }
}
