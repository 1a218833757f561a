package rtd.accel;

import rtd.camera.PerspectiveCamera;
import rtd.geometry.IGeometry;
import rtd.math.Vector3f;

/**
 * The {@link ImageFootprint} of an object for the perspective camera: its grown box as the eye
 * sees it.
 *
 * <p>Every ray leaves the eye O along {@code D = F·f + u·x' + v·y'} (Part II, "The perspective
 * camera"), so a point P that a ray meets, {@code P − O = t·D}, shows at
 * {@code x' = f·((P − O)·u)/((P − O)·F)}, and likewise y'. A box wholly in front of the eye shows
 * within the rectangle of its eight corners' pictures. A box that reaches behind the plane of the
 * eye is only bounded from one side: a point at depth {@code c ≤ cmax} with
 * {@code (P − O)·u ≥ a > 0} shows at {@code x' ≥ f·a/cmax}, however near the eye it lies. The
 * rectangle is widened by what the rounding of the rays' float directions and of the image axes
 * can move a ray: a few thousandths of a pixel, and a hundred times that is kept.
 */
final class PerspectiveFootprint implements ImageFootprint {

    /** A pixel's share of rounding, relative to {@code f + w + h}, with ample room: see the class comment. */
    private static final double DIRECTION_ERROR = 1e-5;

    private final Vector3f eye;
    /** Whether the rays' directions are in the range {@link KnownShapes#roundingFrom} speaks of. */
    private final boolean raysInRange;
    private final double ox;
    private final double oy;
    private final double oz;
    private final double[] forward;
    private final double[] right;
    private final double[] down;
    private final double focal;
    private final int width;
    private final int height;
    private final int halfWidth;
    private final int halfHeight;
    private final double latestOffset;
    /** How far a ray's picture may lie from where exact arithmetic puts it, in pixels. */
    private final double margin;
    /**
     * How far behind the eye's plane a ray may run, per unit it runs: {@code D·F} is about f, but
     * rounding can take it below 0 where f is tiny beside the picture (a field of view near 180°).
     */
    private final double backward;

    PerspectiveFootprint(PerspectiveCamera camera, int width, int height, double latestOffset) {
        eye = camera.position();
        ox = eye.x();
        oy = eye.y();
        oz = eye.z();
        forward = ImageFootprint.numbers(camera.forward());
        right = ImageFootprint.numbers(camera.widthVector());
        down = ImageFootprint.numbers(camera.heightVector());
        focal = camera.focalLength(width);
        this.width = width;
        this.height = height;
        halfWidth = width / 2; // as the camera divides
        halfHeight = height / 2;
        this.latestOffset = latestOffset;
        double size = Math.abs(focal) + width + height;
        margin = DIRECTION_ERROR * size * (1 + (width + height) / Math.abs(focal));
        backward = Math.max(1e-9, DIRECTION_ERROR * (width + height) / Math.abs(focal));
        raysInRange = directionsInRange(forward, right, down, focal, width, height);
    }

    /**
     * Every ray leaves the eye: a shape may round less for such rays ({@link KnownShapes#roundingFrom}),
     * if their directions' lengths are in its range, as any camera's but the most extreme are.
     */
    @Override
    public Rounding roundingOf(IGeometry object, float[] box) {
        return raysInRange ? KnownShapes.roundingFrom(object, eye, box, 0) : KnownShapes.rounding(object);
    }

    /** {@link #raysInRange}, for tests. */
    boolean raysInRange() {
        return raysInRange;
    }

    /**
     * Whether every ray's direction {@code R = F·f + u·x' + v·y'} has
     * {@link KnownShapes#SHORTEST_DIRECTION} ≤ |R|₁ ≤ {@link KnownShapes#LONGEST_DIRECTION}: |R|₁ is at
     * most the sum of the parts' and at least |R| ≥ |R·F|/|F|, for offsets up to half the picture
     * and a pixel more, with room for rounding.
     */
    private static boolean directionsInRange(double[] forward, double[] across, double[] down, double focal, int width,
            int height) {
        double x = width / 2.0 + 2;
        double y = height / 2.0 + 2;
        double longest = (Math.abs(focal) * sum(forward) + x * sum(across) + y * sum(down)) * (1 + 1e-5);
        double forwardLength = Math.sqrt(ImageFootprint.dot(forward, forward));
        double shortest = (Math.abs(focal) * forwardLength * forwardLength
                - x * Math.abs(ImageFootprint.dot(across, forward)) - y * Math.abs(ImageFootprint.dot(down, forward)))
                / forwardLength * (1 - 1e-5);
        return shortest >= KnownShapes.SHORTEST_DIRECTION && longest <= KnownShapes.LONGEST_DIRECTION;
    }

    private static double sum(double[] v) {
        return Math.abs(v[0]) + Math.abs(v[1]) + Math.abs(v[2]);
    }

    @Override
    public float put(float[] boxes, int at, float linear, float quadratic, int[] into, int to) {
        double x0 = boxes[at] - ox;
        double y0 = boxes[at + 1] - oy;
        double z0 = boxes[at + 2] - oz;
        double x1 = boxes[at + 3] - ox;
        double y1 = boxes[at + 4] - oy;
        double z1 = boxes[at + 5] - oz;
        double widest = linear + KnownShapes.ROUNDING_CONE;
        // a hit runs L ≤ farthest corner + √3·growth(L) ≤ farthest + √3·widest·L from the eye
        double farthest = ImageFootprint.farthest(x0, y0, z0, x1, y1, z1);
        double reach = farthest / (1 - Math.sqrt(3) * widest);
        double grow = ImageFootprint.growth(linear, quadratic, reach);
        double nearest = ImageFootprint.distance(x0, y0, z0, x1, y1, z1) - Math.sqrt(3) * grow;
        if (!(widest * Math.sqrt(3) < 0.5 && Double.isFinite(grow))) {
            return ImageFootprint.whole(width, height, into, to);
        }
        x0 -= grow;
        y0 -= grow;
        z0 -= grow;
        x1 += grow;
        y1 += grow;
        z1 += grow;
        // the corners' least and largest depth along F, and sides along u and v: sums of each axis' least and largest
        double depthLeast = ImageFootprint.leastAlong(x0, y0, z0, x1, y1, z1, forward);
        double depthMost = ImageFootprint.mostAlong(x0, y0, z0, x1, y1, z1, forward);
        if (depthMost < -reach * backward) {
            return Float.NaN; // wholly behind the eye: a ray's points have (P − O)·F = t·D·F ≥ 0, give or take rounding
        }
        double left;
        double rightmost;
        double top;
        double bottom;
        if (depthLeast > 1e-6 * depthMost) { // wholly in front: the corners' pictures bound it
            left = Double.POSITIVE_INFINITY;
            rightmost = Double.NEGATIVE_INFINITY;
            top = Double.POSITIVE_INFINITY;
            bottom = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < 8; k++) {
                double x = (k & 1) == 0 ? x0 : x1;
                double y = (k & 2) == 0 ? y0 : y1;
                double z = (k & 4) == 0 ? z0 : z1;
                double scale = focal / (x * forward[0] + y * forward[1] + z * forward[2]);
                double across = (x * right[0] + y * right[1] + z * right[2]) * scale;
                double down = (x * this.down[0] + y * this.down[1] + z * this.down[2]) * scale;
                left = Math.min(left, across);
                rightmost = Math.max(rightmost, across);
                top = Math.min(top, down);
                bottom = Math.max(bottom, down);
            }
        } else if (!(depthMost > 0)) { // at the eye's plane, give or take rounding: anywhere
            left = Double.NEGATIVE_INFINITY;
            rightmost = Double.POSITIVE_INFINITY;
            top = Double.NEGATIVE_INFINITY;
            bottom = Double.POSITIVE_INFINITY;
        } else { // reaching behind the eye's plane: a side is bounded only where the box keeps to it
            double acrossLeast = ImageFootprint.leastAlong(x0, y0, z0, x1, y1, z1, right);
            double acrossMost = ImageFootprint.mostAlong(x0, y0, z0, x1, y1, z1, right);
            double downLeast = ImageFootprint.leastAlong(x0, y0, z0, x1, y1, z1, this.down);
            double downMost = ImageFootprint.mostAlong(x0, y0, z0, x1, y1, z1, this.down);
            left = acrossLeast > 0 ? focal * acrossLeast / depthMost : Double.NEGATIVE_INFINITY;
            rightmost = acrossMost < 0 ? focal * acrossMost / depthMost : Double.POSITIVE_INFINITY;
            top = downLeast > 0 ? focal * downLeast / depthMost : Double.NEGATIVE_INFINITY;
            bottom = downMost < 0 ? focal * downMost / depthMost : Double.POSITIVE_INFINITY;
        }
        if (Double.isNaN(left) || Double.isNaN(rightmost) || Double.isNaN(top) || Double.isNaN(bottom)) {
            return ImageFootprint.whole(width, height, into, to);
        }
        return ImageFootprint.rectangle(halfWidth + left - margin, halfWidth + rightmost + margin,
                halfHeight + top - margin, halfHeight + bottom + margin, width, height, latestOffset, nearest, into,
                to);
    }
}
