package rtd.geometry;

import rtd.math.Vector3f;

/**
 * The intersection test of a ray and a triangle, on the triangle's {@value Triangle#NUMBERS}
 * numbers, worked out once from its corners ({@link #putNumbers}) and kept as plain floats (a
 * mesh can have millions): it first finds where the ray meets the triangle's plane, then asks on
 * which side of each edge that point lies. Written once: {@link Triangle#intersect} runs it on a
 * triangle's numbers, the engine on the same numbers without making a ray, and {@code --explain}
 * watches it through a {@link TestObserver}.
 *
 * <p>Each side test is a dot product with a vector fixed per edge ({@code n × edge}, in the
 * plane, pointing inwards), so its rounding error, as a distance, is a few units of the last
 * place of the distances involved: a reported hit is never far from the triangle, however thin
 * it is or however flat the ray comes in. A triangle of zero area
 * has {@code n = 0}, no ray meets its plane, and it is never hit.
 */
public final class RayTriangle {

    // Where each of the test's numbers stands in its array (Triangle.numbers, which the engine reads too).
    static final int CORNERS = 0;        // p1, p2, p3: x, y, z each
    static final int NORMAL = 9;         // n = (p2 − p1) × (p3 − p1)
    static final int INWARD = 12;        // n × edge, for the edges from p1, p2, p3
    static final int INWARD_LENGTH = 21; // |n × edge|, for the three edges
    static final int TOLERANCE = 24;     // the side tests' allowance per unit of distance from a corner
    static final int NORMAL_SUM = 25;    // |nx| + |ny| + |nz|
    static final int SIZE = 26;          // the edges' lengths, summed over the axes
    static final float U = 0x1p-24f; // the unit roundoff of float

    /**
     * The largest share of the distance run by which the side tests let a hit stray along the
     * ray (see {@link #hit}).
     */
    public static final float ALONG_THE_RAY = 1e-4f;

    private RayTriangle() {
    }

    /**
     * The test on the {@value Triangle#NUMBERS} numbers of {@link Triangle#numbers}, starting
     * at {@code v[at]}: t of the hit, or NaN. Public for the engine, which runs it on a
     * triangle's numbers where they lie.
     *
     * <p>Each side test allows for its own rounding: a point within a few units of the last
     * place of an edge counts as on it. Without that, a ray through an edge that two triangles
     * of a mesh share could slip between them, as each triangle finds its own P and rounds its
     * own way, and the mesh would show cracks. The allowance has three parts: the rounding of
     * the side test itself ({@code (P − p)} times the normal's uncertainty, larger for a thin
     * triangle), of P's coordinates, and of t along the ray, which grows as the ray comes in
     * flatter, up to {@value #ALONG_THE_RAY} of the distance run.
     */
    public static float hit(float[] v, int at, float ox, float oy, float oz, float dx, float dy, float dz,
            TestObserver watch) {
        float facing = (dx * v[at + NORMAL]) + (dy * v[at + NORMAL + 1]) + (dz * v[at + NORMAL + 2]);          // R·n
        float along = ((v[at] - ox) * v[at + NORMAL]) + ((v[at + 1] - oy) * v[at + NORMAL + 1])
                + ((v[at + 2] - oz) * v[at + NORMAL + 2]);                                                 // (p1 − O)·n
        float t = along / facing;
        watch.plane(facing, along, t);
        if (!(t >= 0) || facing == 0 || Float.isInfinite(t)) {
            return Float.NaN;
        }
        float px = ox + dx * t; // as Ray.pointAt rounds it
        float py = oy + dy * t;
        float pz = oz + dz * t;
        float loose = looseness(v, at, px, py, pz, dx, dy, dz, t, facing);
        boolean near = nearTheCorners(v, at, px, py, pz, loose);
        watch.trianglePoint(px, py, pz, loose, near);
        if (!near) {
            return Float.NaN; // the allowances must not stretch a hit far beyond the corners
        }
        return inside(v, at, 0, px, py, pz, loose, watch) && inside(v, at, 1, px, py, pz, loose, watch)
                && inside(v, at, 2, px, py, pz, loose, watch) ? t : Float.NaN;
    }

    /** Whether P lies on the triangle's side of edge {@code k}, up to the rounding allowed. */
    private static boolean inside(float[] v, int at, int k, float px, float py, float pz, float loose,
            TestObserver watch) {
        float side = side(v, at, k, px, py, pz);
        float allowance = allowance(v, at, k, px, py, pz, loose);
        watch.triangleSide(k, side, allowance);
        return side >= -allowance;
    }

    /**
     * The part of the side tests' allowance that does not depend on the edge: the rounding of
     * P's coordinates, and of t along the ray, which grows as the ray comes in flatter
     * ({@code |R|·|n| / |R·n|}), up to {@value #ALONG_THE_RAY} of the distance run.
     */
    static float looseness(float[] v, int at, float px, float py, float pz, float dx, float dy, float dz, float t,
            float facing) {
        float length = Math.abs(dx) + Math.abs(dy) + Math.abs(dz);
        float along = Math.min(ALONG_THE_RAY, 16 * U * (1 + length * v[at + NORMAL_SUM] / Math.abs(facing)));
        return 16 * U * (Math.abs(px) + Math.abs(py) + Math.abs(pz)) + along * t * length;
    }

    /** Whether P lies within the allowances of the corners' box, on every axis. */
    static boolean nearTheCorners(float[] v, int at, float px, float py, float pz, float loose) {
        float reach = v[at + TOLERANCE] * v[at + SIZE] + loose;
        return near(v, at, 0, px, reach) && near(v, at, 1, py, reach) && near(v, at, 2, pz, reach);
    }

    /**
     * How far below 0 the side test of edge {@code k} (from corner k to the next) may come and
     * still count P as inside: the side test's own rounding, and {@code loose}.
     */
    static float allowance(float[] v, int at, int k, float px, float py, float pz, float loose) {
        int corner = at + CORNERS + 3 * k;
        float fromCorner = Math.abs(px - v[corner]) + Math.abs(py - v[corner + 1]) + Math.abs(pz - v[corner + 2]);
        return (v[at + TOLERANCE] * fromCorner + loose) * v[at + INWARD_LENGTH + k];
    }

    /** {@code (P − corner k)·(n × edge k)}: ≥ 0 when P lies on the triangle's side of edge k. */
    public static float side(float[] v, int at, int k, float px, float py, float pz) {
        return dotFrom(v, at + CORNERS + 3 * k, at + INWARD + 3 * k, px, py, pz);
    }

    /** Whether coordinate {@code axis} of P is within {@code reach} of the corners' range. */
    private static boolean near(float[] v, int at, int axis, float p, float reach) {
        float a = v[at + CORNERS + axis];
        float b = v[at + CORNERS + 3 + axis];
        float c = v[at + CORNERS + 6 + axis];
        return p >= Math.min(a, Math.min(b, c)) - reach && p <= Math.max(a, Math.max(b, c)) + reach;
    }

    /** {@code (P − corner)·inward}, with both given by where they start in {@code v}. */
    private static float dotFrom(float[] v, int corner, int inward, float px, float py, float pz) {
        return ((px - v[corner]) * v[inward]) + ((py - v[corner + 1]) * v[inward + 1])
                + ((pz - v[corner + 2]) * v[inward + 2]);
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

    /**
     * {@code |q − p|} of the points whose x, y, z start at
     * {@code v[p]} and {@code v[q]}, as {@link Vector3f} works it out.
     */
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
