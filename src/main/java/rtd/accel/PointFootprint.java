package rtd.accel;

import rtd.geometry.IGeometry;
import rtd.math.Vector3f;

/**
 * The {@link ImageFootprint} of an object seen from a point X, for the shadow rays towards a light at
 * X (Part II, "Shadows"), which run from a surface to the light ({@link #around}). The "image" is a
 * square picture, {@code size × size} pixels, of the directions from X towards the scene's objects:
 * direction w shows at {@code ((w·u)/(w·F), (w·v)/(w·F))}, scaled to pixels, for a forward direction F
 * towards the middle of the objects' box and u, v across it: POV-Ray's "light buffer", made exact.
 *
 * <p>A ray {@code O + t·D} that reaches {@code E = O + (d/|D|)·D} at distance d is
 * served if {@code |E − X|} is at most a small gap g and {@code d} at most a reach R. Every point Q
 * between O and E is then {@code (1 − s)(O − X) + s(E − X)} from X, so seen from X it lies within
 * an angle of about {@code g/|Q − X|} of O. A hit at Q that the test reports lies in the object's
 * box grown by its rounding at the distance the ray has run, {@code |Q − O|}, at most
 * {@code R − |Q − X| + g}; so the ray's pixel, the one of {@code O − X}, lies in the picture of that
 * grown box widened by that angle, which is the footprint. The answer of {@link #put} is the
 * distance from X to the grown box: a ray whose origin lies nearer X than that, by more than the
 * gap, cannot hit the object.
 */
final class PointFootprint implements ImageFootprint {

    /**
     * The gap served, relative to {@code R + |X|}: a shadow ray from the shader ends at the
     * light within a few float roundings of its length and position (about 1e-7 of them); this
     * leaves twenty times that.
     */
    static final double GAP = 2e-6;

    /** The point X: the light. */
    private final double pointX;
    private final double pointY;
    private final double pointZ;
    private final double[] forward;
    private final double[] across;
    private final double[] down;
    private final int size;
    private final double half;
    /** Pixels per unit of tangent. */
    private final double scale;
    private final double reach;
    private final double gap;

    private PointFootprint(Vector3f point, double[][] axes, double widest, int size, double reach, double gap) {
        pointX = point.x();
        pointY = point.y();
        pointZ = point.z();
        this.forward = axes[0];
        this.across = axes[1];
        this.down = axes[2];
        this.size = size;
        this.half = size / 2.0;
        this.scale = size / (2 * widest);
        this.reach = reach;
        this.gap = gap;
    }

    /**
     * The footprints seen from {@code point} on a picture of {@code size × size} pixels that shows
     * the box {@code box} (min x, y, z, max x, y, z), for rays towards the point that run up to
     * 1.25 times as far as the box's farthest corner is from the point, and at most a diagonal of
     * the box farther (the shadow rays from the objects, and from the floor beneath them). The
     * picture's axes are F towards the box's middle, u level across it and v down it. Null if the
     * box is not all well in front of the point (each corner within 87° of F, a tangent of 20, and
     * a twentieth of the distance to the middle ahead), as when the point lies inside it or beside
     * it; or if the point lies so far that the gap is more than a few hundredths of the box's picture.
     */
    static PointFootprint around(Vector3f point, float[] box, int size) {
        double[] toMiddle = {(box[0] + box[3]) / 2.0 - point.x(), (box[1] + box[4]) / 2.0 - point.y(),
                (box[2] + box[5]) / 2.0 - point.z()};
        double distance = Math.sqrt(ImageFootprint.dot(toMiddle, toMiddle));
        if (!(distance > 0 && Double.isFinite(distance))) {
            return null;
        }
        double[] forward = scaled(toMiddle, 1 / distance);
        double[] up = Math.abs(forward[1]) < 0.9 ? new double[] {0, 1, 0} : new double[] {0, 0, 1};
        double[] level = cross(up, forward);
        double[] across = scaled(level, 1 / Math.sqrt(ImageFootprint.dot(level, level)));
        double[] down = cross(forward, across);
        double widest = 0;
        double farthest = 0;
        for (int k = 0; k < 8; k++) {
            double[] w = {box[(k & 1) * 3] - point.x(), box[1 + (k >> 1 & 1) * 3] - point.y(),
                    box[2 + (k >> 2 & 1) * 3] - point.z()};
            double depth = ImageFootprint.dot(w, forward);
            if (!(depth > distance / 20)) {
                return null;
            }
            double side = Math.max(Math.abs(ImageFootprint.dot(w, across)), Math.abs(ImageFootprint.dot(w, down)));
            widest = Math.max(widest, side / depth);
            farthest = Math.max(farthest, Math.sqrt(ImageFootprint.dot(w, w)));
        }
        widest = Math.max(widest * 1.01, 1e-6); // a hundredth of room at the picture's edges; never 0
        double diagonal = Math.sqrt(Math.pow(box[3] - box[0], 2) + Math.pow(box[4] - box[1], 2)
                + Math.pow(box[5] - box[2], 2));
        // rays from beyond the box, but not from much farther: every object grows by its rounding at the
        // reach less its distance, which for a far light would grow with the light's distance
        double reach = Math.min(1.25 * farthest, farthest + diagonal);
        // the float rounding of a ray's end grows with its length and with the size of the coordinates
        double gap = GAP * (reach + Math.sqrt((double) point.x() * point.x() + (double) point.y() * point.y()
                + (double) point.z() * point.z()));
        boolean tooNarrow = gap > 0.08 * distance * widest; // the tree does better
        double[][] axes = {forward, across, down};
        return widest > 20 || tooNarrow ? null : new PointFootprint(point, axes, widest, size, reach, gap);
    }

    private static double[] scaled(double[] a, double factor) {
        return new double[] {a[0] * factor, a[1] * factor, a[2] * factor};
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /** The largest gap served, g. */
    double gap() {
        return gap;
    }

    /** The longest ray served ({@code d ≤ R}). */
    double reach() {
        return reach;
    }

    /**
     * The pixel, as {@code y·size + x}, of the ray from {@code (ox, oy, oz)} that reaches
     * {@code (ex, ey, ez)} at its end, if it is served: its end lies within the gap of X, it
     * runs at most R, and it shows on the picture; else −1.
     */
    int pixelOf(double ox, double oy, double oz, double ex, double ey, double ez, double length) {
        double gx = ex - pointX;
        double gy = ey - pointY;
        double gz = ez - pointZ;
        if (!(length <= reach && gx * gx + gy * gy + gz * gz <= gap * gap)) {
            return -1;
        }
        return pixelOfDirection(ox - pointX, oy - pointY, oz - pointZ);
    }

    /** The pixel, as {@code y·size + x}, in which direction w from X shows, or −1 if not on the picture. */
    private int pixelOfDirection(double wx, double wy, double wz) {
        double depth = wx * forward[0] + wy * forward[1] + wz * forward[2];
        double x = half + scale * (wx * across[0] + wy * across[1] + wz * across[2]) / depth;
        double y = half + scale * (wx * down[0] + wy * down[1] + wz * down[2]) / depth;
        if (!(depth > 0 && x >= 0 && x < size && y >= 0 && y < size)) {
            return -1;
        }
        return (int) y * size + (int) x;
    }

    @Override
    public float put(float[] boxes, int at, float linear, float quadratic, int[] into, int to) {
        double x0 = boxes[at] - pointX;
        double y0 = boxes[at + 1] - pointY;
        double z0 = boxes[at + 2] - pointZ;
        double x1 = boxes[at + 3] - pointX;
        double y1 = boxes[at + 4] - pointY;
        double z1 = boxes[at + 5] - pointZ;
        double run = run(x0, y0, z0, x1, y1, z1, ImageFootprint.growth(linear, quadratic, reach)) * (1 + 1e-6);
        double grow = ImageFootprint.growth(linear, quadratic, run);
        x0 -= grow;
        y0 -= grow;
        z0 -= grow;
        x1 += grow;
        y1 += grow;
        z1 += grow;
        double nearest = ImageFootprint.distance(x0, y0, z0, x1, y1, z1);
        double depthLeast = ImageFootprint.leastAlong(x0, y0, z0, x1, y1, z1, forward);
        // a box near X, or beside or behind it, may be hit by a ray of any pixel: a guard, as around()
        // admits only boxes well in front
        if (!(depthLeast > 4 * gap && nearest > 4 * gap)) {
            return ImageFootprint.whole(size, size, into, to);
        }
        double left = Double.POSITIVE_INFINITY;
        double right = Double.NEGATIVE_INFINITY;
        double top = Double.POSITIVE_INFINITY;
        double bottom = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < 8; k++) {
            double x = (k & 1) == 0 ? x0 : x1;
            double y = (k & 2) == 0 ? y0 : y1;
            double z = (k & 4) == 0 ? z0 : z1;
            double depth = x * forward[0] + y * forward[1] + z * forward[2];
            double sideways = (x * across[0] + y * across[1] + z * across[2]) / depth;
            double downwards = (x * down[0] + y * down[1] + z * down[2]) / depth;
            left = Math.min(left, sideways);
            right = Math.max(right, sideways);
            top = Math.min(top, downwards);
            bottom = Math.max(bottom, downwards);
        }
        // an angle a moves a point of the picture by at most (1 + its tangents²)·a; sin a ≤ g/|Q − X|,
        // and a ≤ 1.02·sin a for the angles here, taken as 1.6 with room; the tangents are the larger of
        // the box's and the picture's, as the ray's origin may show anywhere on it; twice that, for room
        double angle = 1.6 * gap * (1 + 1e-6) / (nearest - gap);
        double wideX = Math.max(Math.max(-left, right), half / scale);
        double wideY = Math.max(Math.max(-top, bottom), half / scale);
        double margin = 2 * scale * (1 + wideX * wideX + wideY * wideY) * angle + 1e-6 * size;
        if (!Double.isFinite(margin)) {
            return ImageFootprint.whole(size, size, into, to);
        }
        // a ray shows at a point c of the picture, in pixel floor(c): a pixel covers [p, p + 1), hence the 1
        return ImageFootprint.rectangle(half + scale * left - margin, half + scale * right + margin,
                half + scale * top - margin, half + scale * bottom + margin, size, size, 1, nearest, into, to);
    }

    /**
     * How far a ray can have run to a hit in the box {@code (x0 .. z1)} (relative to X) grown by at
     * most {@code mostGrowth}: a hit Q lies at most {@code R − |Q − X| + g} from the origin, and
     * |Q − X| is at least the box's distance less √3 growths, so near the light hits come from far.
     */
    private double run(double x0, double y0, double z0, double x1, double y1, double z1, double mostGrowth) {
        double unGrown = ImageFootprint.distance(x0, y0, z0, x1, y1, z1);
        return Math.min(reach, reach - unGrown + Math.sqrt(3) * mostGrowth + gap);
    }
}
