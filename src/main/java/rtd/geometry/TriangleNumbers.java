package rtd.geometry;

import rtd.math.Vector3f;

/**
 * The {@value Triangle#NUMBERS} numbers a triangle's intersection test reads, worked out once
 * from its corners: where each one stands in the array, and how {@link #putNumbers} computes
 * them. {@link Triangle} keeps them (alone, or in its mesh's one array), and {@link RayTriangle}
 * tests a ray against them, for the triangle's {@code intersect} and for the engine alike.
 *
 * <p>The corners and the per-edge vectors are kept as plain floats: a mesh can have millions.
 */
public final class TriangleNumbers {

    // Where each of the test's numbers stands in its array (Triangle.numbers, which the engine reads too).
    static final int CORNERS = 0;        // p1, p2, p3: x, y, z each
    static final int NORMAL = 9;         // n = (p2 − p1) × (p3 − p1)
    static final int INWARD = 12;        // n × edge, for the edges from p1, p2, p3
    static final int INWARD_LENGTH = 21; // |n × edge|, for the three edges
    static final int TOLERANCE = 24;     // the side tests' allowance per unit of distance from a corner
    static final int NORMAL_SUM = 25;    // |nx| + |ny| + |nz|
    static final int SIZE = 26;          // the edges' lengths, summed over the axes
    static final float U = 0x1p-24f; // the unit roundoff of float

    private TriangleNumbers() {
    }

    /**
     * Writes the {@value Triangle#NUMBERS} numbers of the triangle with corners p1, p2, p3 into
     * {@code into} from {@code at}: the corners, the normal n, the per-edge vectors and their
     * lengths, the tolerance, and the sums (in the order of the constants above).
     */
    public static void putNumbers(Vector3f p1, Vector3f p2, Vector3f p3, float[] into, int at) {
        Vector3f edge1 = p2.subtract(p1); // each difference once: a mesh makes a million triangles
        Vector3f edge2 = p3.subtract(p2);
        Vector3f edge3 = p1.subtract(p3);
        Vector3f n = edge1.cross(p3.subtract(p1));
        Vector3f in1 = n.cross(edge1);
        Vector3f in2 = n.cross(edge2);
        Vector3f in3 = n.cross(edge3);
        float tolerance = tolerance(thinness(edge1.magnitude(), edge2.magnitude(), edge3.magnitude(), n.magnitude()));
        float nSum = Math.abs(n.x()) + Math.abs(n.y()) + Math.abs(n.z());
        float size = sum(edge1) + sum(edge2) + sum(edge3);
        put(p1, into, at + CORNERS);
        put(p2, into, at + CORNERS + 3);
        put(p3, into, at + CORNERS + 6);
        put(n, into, at + NORMAL);
        put(in1, into, at + INWARD);
        put(in2, into, at + INWARD + 3);
        put(in3, into, at + INWARD + 6);
        into[at + INWARD_LENGTH] = in1.magnitude();
        into[at + INWARD_LENGTH + 1] = in2.magnitude();
        into[at + INWARD_LENGTH + 2] = in3.magnitude();
        into[at + TOLERANCE] = tolerance;
        into[at + NORMAL_SUM] = nSum;
        into[at + SIZE] = size;
    }

    private static void put(Vector3f p, float[] into, int at) {
        into[at] = p.x();
        into[at + 1] = p.y();
        into[at + 2] = p.z();
    }

    private static float sum(Vector3f v) {
        return Math.abs(v.x()) + Math.abs(v.y()) + Math.abs(v.z());
    }

    /**
     * How much less certain the normal's direction is than its length suggests, and how thin
     * the triangle is: one over the sine of its smallest angle, {@code |ei||ej| / |n|} at most;
     * about 1 for a well-shaped triangle, large for a needle. Of the triangle whose numbers
     * {@link #putNumbers} wrote into {@code v} from {@code at}.
     */
    static double thinness(float[] v, int at) {
        int p1 = at + CORNERS;
        return thinness(distance(v, p1, p1 + 3), distance(v, p1 + 3, p1 + 6), distance(v, p1 + 6, p1),
                length(v[at + NORMAL], v[at + NORMAL + 1], v[at + NORMAL + 2]));
    }

    /** {@link #thinness(float[], int)} from the lengths of the edges p1 → p2 → p3 → p1 and of the normal. */
    private static double thinness(double e1, double e2, double e3, double n) {
        double longest = Math.max(e1 * e2, Math.max(e2 * e3, e3 * e1));
        return n > 0 ? Math.max(1, longest / n) : 1; // never hit if n = 0
    }

    /** {@code |q − p|} of the points whose x, y, z start at {@code v[p]} and {@code v[q]}, as {@link Vector3f} works it out. */
    static float distance(float[] v, int p, int q) {
        return length(v[q] - v[p], v[q + 1] - v[p + 1], v[q + 2] - v[p + 2]);
    }

    /** {@link Vector3f#magnitude} of (x, y, z). */
    private static float length(float x, float y, float z) {
        return (float) Math.sqrt(x * x + y * y + z * z);
    }

    /**
     * The side tests' allowance per unit of distance from the corner: the rounding of the
     * normal's direction, {@code 16u · thinness}; none for a needle (thinness over 128), whose
     * own rounding is too coarse to hold its edges together anyway, and which an allowance
     * would lengthen.
     */
    private static float tolerance(double thinness) {
        return thinness <= 128 ? 16 * U * (float) thinness : 0;
    }
}
