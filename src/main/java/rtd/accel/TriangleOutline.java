package rtd.accel;

import rtd.geometry.Triangle;
import rtd.math.Vector3f;

/**
 * A triangle's picture through the perspective camera, grown by what rounding can move a hit:
 * three edges on the image, each a half-plane {@code a·x + b·y + c ≥ 0} of ray positions (in
 * pixels, as {@link PerspectiveFootprint} counts them). Not in the paper; the {@link ViewGrid}
 * puts a triangle into the cells of its rectangle that its outline overlaps, about half of them
 * for the small triangles of a mesh.
 *
 * <p>Why a hit's ray passes within a distance Δ of the triangle itself, not just of its box: the
 * test ({@link Triangle#hit}) accepts a point P when P lies on the inner side of each edge,
 * allowing {@code tol·|P − corner| + loose} ({@link Triangle#looseness}). So P lies in the
 * triangle with each edge moved out by about that much, g, in the triangle's plane; the corner
 * between two moved edges lies {@code g / sin(α/2)} from the triangle's, for a corner angle α.
 * Off the plane, P strays only by the rounding of t times {@code D·n̂}, which is small even for a
 * ray that comes in flat: t errs along the ray, not away from the plane. The ray's own point
 * {@code O + t·D} lies within the rounding of P's coordinates of P. The part of the allowance
 * that grows as the ray comes in flatter, {@code 16u·|D|₁|n|₁ / |D·n|}, is bounded per
 * triangle: {@code |D·n̂| / |D|} is the eye's distance from the plane over the distance run.
 * All of that, doubled, is Δ.
 *
 * <p>A point moved by Δ at depth z shows at most {@code f·Δ/z · (1 + |x|/f)} pixels away, for a
 * picture x measured from the middle. So the triangle's three corners' pictures, with each
 * edge pushed out by that much and by the rounding of the camera's rays
 * ({@link PerspectiveFootprint}), bound every pixel whose ray the test lets hit it. Where these
 * numbers do not bound it well (a needle, a triangle seen edge on, or reaching near the eye's
 * plane), there is no outline, and the rectangle alone serves.
 */
final class TriangleOutline {

    /** How many numbers an outline takes: a, b, c for each of the three edges. */
    static final int NUMBERS = 9;
    private static final double U = 0x1p-24; // float's unit roundoff
    private static final double ROOT_3 = Math.sqrt(3);
    /** The thinnest corner outlined, as {@code 1 / sin(α/2)}: about 7°. */
    private static final double MOST_CORNER_FACTOR = 16;
    /** The flattest view outlined: the eye's distance from the plane against the longest run. */
    private static final double LEAST_HEIGHT = 1e-3;
    /** The widest growth outlined, in pixels: beyond it the rectangle is as good. */
    private static final double MOST_GROWTH = 64;

    private final double ox;
    private final double oy;
    private final double oz;
    private final double[] forward;
    private final double[] right;
    private final double[] down;
    private final double focal;
    private final double halfWidth;
    private final double halfHeight;
    /** How far rounding moves a camera ray's picture, in pixels ({@link PerspectiveFootprint}). */
    private final double margin;

    TriangleOutline(Vector3f eye, double[] forward, double[] right, double[] down, double focal, int halfWidth,
            int halfHeight, double margin) {
        this.ox = eye.x();
        this.oy = eye.y();
        this.oz = eye.z();
        this.forward = forward;
        this.right = right;
        this.down = down;
        this.focal = Math.abs(focal);
        this.halfWidth = halfWidth;
        this.halfHeight = halfHeight;
        this.margin = margin;
    }

    /**
     * Writes the outline of {@code triangle}, whose hits run at most {@code reach} from the eye,
     * into {@code into[to .. to+8]}; false, and nothing written, where it has none.
     */
    boolean put(Triangle triangle, double reach, float[] into, int to) {
        double tolerance = triangle.sideTolerance();
        double size = triangle.edgeSum();
        double[] x = new double[3];
        double[] y = new double[3];
        double[] z = new double[3];
        for (int k = 0; k < 3; k++) {
            Vector3f corner = triangle.corner(k);
            x[k] = corner.x() - ox;
            y[k] = corner.y() - oy;
            z[k] = corner.z() - oz;
        }
        double corners = 0; // the largest |corner|₁, from the origin of the world
        for (int k = 0; k < 3; k++) {
            Vector3f corner = triangle.corner(k);
            corners = Math.max(corners, Math.abs(corner.x()) + Math.abs(corner.y()) + Math.abs(corner.z()));
        }
        double height = heightOfEye(x, y, z);
        double cornerFactor = cornerFactor(x, y, z);
        if (!(tolerance > 0 && height >= LEAST_HEIGHT * reach && cornerFactor <= MOST_CORNER_FACTOR)) {
            return false;
        }
        double delta = delta(tolerance, size, corners, height, cornerFactor, reach,
                Math.abs(x[0]) + Math.abs(y[0]) + Math.abs(z[0]));
        return putEdges(x, y, z, delta, into, to);
    }

    /** Δ: how far from the triangle the point of a ray that the test lets hit it can lie (see the class comment). */
    private static double delta(double tolerance, double size, double corners, double height, double cornerFactor,
            double reach, double eyeToCorner) {
        double along = Math.min(Triangle.ALONG_THE_RAY, 16 * U * (1 + 1 / (height / (3 * reach) - 4 * U)));
        double point = corners + size + 3 * (tolerance * size + 32 * U * (corners + size) + along * ROOT_3 * reach);
        double loose = 1.01 * (16 * U * point + along * ROOT_3 * reach);
        double fromCorner = size + 3 * (tolerance * size + loose); // |P − corner|₁, within the corners' reach
        double outward = 2.1 * tolerance * fromCorner + 1.01 * loose + 13 * U * fromCorner;
        double inPlane = outward * cornerFactor;
        double rounded = 1.01 * U * (ROOT_3 * reach + point); // |O + t·D − P|
        double offPlane = 10 * U * (eyeToCorner + reach + height) + tolerance * (fromCorner + inPlane);
        return 2 * (2 * rounded + inPlane + offPlane);
    }

    /** The eye's distance from the triangle's plane; corners relative to the eye. */
    private static double heightOfEye(double[] x, double[] y, double[] z) {
        double ax = x[1] - x[0];
        double ay = y[1] - y[0];
        double az = z[1] - z[0];
        double bx = x[2] - x[0];
        double by = y[2] - y[0];
        double bz = z[2] - z[0];
        double nx = ay * bz - az * by;
        double ny = az * bx - ax * bz;
        double nz = ax * by - ay * bx;
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        return Math.abs(x[0] * nx + y[0] * ny + z[0] * nz) / length; // NaN for no area: no outline
    }

    /** {@code 1 / sin(α/2)} for the triangle's smallest corner angle α, a little more. */
    private static double cornerFactor(double[] x, double[] y, double[] z) {
        double least = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            int i = (k + 1) % 3;
            int j = (k + 2) % 3;
            double ax = x[i] - x[k];
            double ay = y[i] - y[k];
            double az = z[i] - z[k];
            double bx = x[j] - x[k];
            double by = y[j] - y[k];
            double bz = z[j] - z[k];
            double cos = (ax * bx + ay * by + az * bz)
                    / Math.sqrt((ax * ax + ay * ay + az * az) * (bx * bx + by * by + bz * bz));
            least = Math.min(least, Math.sqrt(Math.max(0, (1 - cos) / 2))); // sin(α/2)
        }
        return 1.001 / least; // NaN or ∞ for no area
    }

    /**
     * The three edges' half-planes through the corners' pictures, each pushed out by what Δ
     * and the rays' rounding can move a picture; false where the corners do not lie well in front
     * of the eye.
     */
    private boolean putEdges(double[] x, double[] y, double[] z, double delta, float[] into, int to) {
        double[] px = new double[3];
        double[] py = new double[3];
        double nearest = Double.POSITIVE_INFINITY;
        double widest = 0;
        double tallest = 0;
        for (int k = 0; k < 3; k++) {
            double depth = x[k] * forward[0] + y[k] * forward[1] + z[k] * forward[2];
            nearest = Math.min(nearest, depth);
            double across = focal * (x[k] * right[0] + y[k] * right[1] + z[k] * right[2]) / depth;
            double downwards = focal * (x[k] * down[0] + y[k] * down[1] + z[k] * down[2]) / depth;
            widest = Math.max(widest, Math.abs(across));
            tallest = Math.max(tallest, Math.abs(downwards));
            px[k] = halfWidth + across;
            py[k] = halfHeight + downwards;
        }
        double least = nearest - length(forward) * delta; // the nearest depth of a point within Δ
        if (!(nearest > 0 && least > nearest / 2)) {
            return false;
        }
        double shift = focal * delta / least;
        double growth = margin + Math.max(shift * (length(right) + length(forward) * widest / focal),
                shift * (length(down) + length(forward) * tallest / focal));
        if (!(growth < MOST_GROWTH)) {
            return false;
        }
        // the cells tested lie within the picture, or near the corners: farther than this from neither
        double span = Math.max(max(px) - min(px), max(py) - min(py)) + 2 * (halfWidth + halfHeight) + 1;
        for (int k = 0; k < 3; k++) {
            if (!putEdge(px, py, k, growth, span, into, to + 3 * k)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The edge from corner {@code k} to the next, as a half-plane that holds the third corner,
     * pushed out by {@code growth} pixels and by the rounding of its float numbers.
     */
    private static boolean putEdge(double[] px, double[] py, int k, double growth, double span, float[] into, int at) {
        int next = (k + 1) % 3;
        int third = (k + 2) % 3;
        float a = (float) -(py[next] - py[k]);
        float b = (float) (px[next] - px[k]);
        double c = -(a * px[k] + b * py[k]);
        if (a * px[third] + b * py[third] + c < 0) {
            a = -a;
            b = -b;
            c = -c;
        }
        // (a, b) is rounded to float: the line turns a little about corner k, by far less than this
        double slack = (Math.abs(a) + Math.abs(b)) * (growth + 1e-6 * span);
        float pushed = Math.nextUp((float) (c + slack));
        if (!(Float.isFinite(a) && Float.isFinite(b) && Float.isFinite(pushed))) {
            return false;
        }
        into[at] = a;
        into[at + 1] = b;
        into[at + 2] = pushed;
        return true;
    }

    /**
     * Whether the outline at {@code outlines[at ..]} overlaps the ray positions
     * {@code [x0, x1] × [y0, y1]}: no edge has all of them outside.
     */
    static boolean overlaps(float[] outlines, int at, double x0, double y0, double x1, double y1) {
        for (int k = at; k < at + NUMBERS; k += 3) {
            double a = outlines[k];
            double b = outlines[k + 1];
            if (a * (a > 0 ? x1 : x0) + b * (b > 0 ? y1 : y0) + outlines[k + 2] < 0) {
                return false;
            }
        }
        return true;
    }

    private static double length(double[] v) {
        return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }

    private static double max(double[] values) {
        return Math.max(values[0], Math.max(values[1], values[2]));
    }

    private static double min(double[] values) {
        return Math.min(values[0], Math.min(values[1], values[2]));
    }
}
