package rtd.accel;

import rtd.math.Vector3f;

/**
 * How a box of objects looks from a point, for a picture of it seen from there
 * ({@link PointFootprint}): the picture's axes (F towards the box's middle, u level across it, v
 * down it), the widest tangent a corner shows at, the farthest corner's distance, the distance
 * to the middle and the box's diagonal.
 */
record PointView(double[] forward, double[] across, double[] down, double widest, double farthest, double distance,
        double diagonal) {

    /** How wide the picture may be: a tangent of at most this from F (87°) on each axis. */
    private static final double WIDEST = 20;

    /**
     * The view of {@code box} (min x, y, z, max x, y, z) from {@code point}; null if the box is
     * not all well in front of the point (within 87° of the direction to its middle, and a
     * twentieth of that distance ahead), as when the point lies inside it or beside it.
     */
    static PointView of(Vector3f point, float[] box) {
        double[] toMiddle = {(box[0] + box[3]) / 2.0 - point.x(), (box[1] + box[4]) / 2.0 - point.y(),
                (box[2] + box[5]) / 2.0 - point.z()};
        double distance = Math.sqrt(dot(toMiddle, toMiddle));
        if (!(distance > 0 && Double.isFinite(distance))) {
            return null;
        }
        double[] forward = scaled(toMiddle, 1 / distance);
        double[] across = perpendicular(forward);
        double[] down = cross(forward, across);
        double widest = 0;
        double farthest = 0;
        for (int k = 0; k < 8; k++) {
            double[] w = {box[(k & 1) * 3] - point.x(), box[1 + (k >> 1 & 1) * 3] - point.y(),
                    box[2 + (k >> 2 & 1) * 3] - point.z()};
            double depth = dot(w, forward);
            if (!(depth > distance / 20)) {
                return null;
            }
            widest = Math.max(widest, Math.max(Math.abs(dot(w, across)), Math.abs(dot(w, down))) / depth);
            farthest = Math.max(farthest, Math.sqrt(dot(w, w)));
        }
        widest = Math.max(widest * 1.01, 1e-6); // a hundredth of room at the picture's edges; never 0
        double diagonal = Math.sqrt(Math.pow(box[3] - box[0], 2) + Math.pow(box[4] - box[1], 2)
                + Math.pow(box[5] - box[2], 2));
        return widest > WIDEST ? null : new PointView(forward, across, down, widest, farthest, distance, diagonal);
    }

    /** Whether a gap of {@code gap} is no longer small beside the box as the point sees it: the tree does better. */
    boolean tooNarrowFor(double gap) {
        return gap > 0.08 * distance * widest;
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] scaled(double[] a, double factor) {
        return new double[] {a[0] * factor, a[1] * factor, a[2] * factor};
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /** A unit vector at right angles to the unit vector {@code a}, level as a camera's x axis is: up × a. */
    private static double[] perpendicular(double[] a) {
        double[] up = Math.abs(a[1]) < 0.9 ? new double[] {0, 1, 0} : new double[] {0, 0, 1};
        double[] c = cross(up, a);
        return scaled(c, 1 / Math.sqrt(dot(c, c)));
    }
}
