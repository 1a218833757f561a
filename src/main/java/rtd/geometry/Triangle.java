package rtd.geometry;

import java.util.Arrays;
import java.util.List;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A triangle with corners p1, p2, p3 (Part II, "Geometry"): the primitive of rasterisation that
 * the paper names (section 3.3.2), and what a mesh is made of. A triangle of a mesh may carry a
 * normal for each corner, blended across it for smooth shading.
 *
 * <p>The test first finds where the ray meets the triangle's plane, then asks on which side of
 * each edge that point lies. Each side test is a dot product with a vector fixed per edge
 * ({@code n × edge}, in the plane, pointing inwards), so its rounding error, as a distance, is
 * a few units of the last place of the distances involved: a reported hit is never far from the
 * triangle, however thin it is or however flat the ray comes in (see {@link IGeometry#bounds}).
 * A triangle of zero area has {@code n = 0}, no ray meets its plane, and it is never hit.
 *
 * <p>The corners and the per-edge vectors are kept as plain floats: a mesh can have millions.
 */
public final class Triangle implements IGeometry {

    // Where each of the test's numbers stands in its array (testNumbers, and the BVH's packed copy).
    private static final int CORNERS = 0;        // p1, p2, p3: x, y, z each
    private static final int NORMAL = 9;         // n = (p2 − p1) × (p3 − p1)
    private static final int INWARD = 12;        // n × edge, for the edges from p1, p2, p3
    private static final int INWARD_LENGTH = 21; // |n × edge|, for the three edges
    private static final int TOLERANCE = 24;     // the side tests' allowance per unit of distance from a corner
    private static final int NORMAL_SUM = 25;    // |nx| + |ny| + |nz|
    private static final int SIZE = 26;          // the edges' lengths, summed over the axes
    /** How many numbers the test uses ({@link #testNumbers}). */
    public static final int NUMBERS = 27;
    private static final float U = 0x1p-24f; // the unit roundoff of float
    /**
     * The largest share of the distance run by which a hit may stray along the ray (see
     * {@link #hit}); the part of {@link #rounding} that grows with the distance.
     */
    private static final float ALONG_THE_RAY = 1e-4f;

    /**
     * p1, p2, p3; n = (p2 − p1) × (p3 − p1); n × edge for the three edges; their lengths; the
     * side tests' tolerance per unit of distance from the corner; |n| summed over the axes; the
     * edges' lengths summed over the axes.
     */
    private final float[] v;
    /** Where this triangle's numbers start in {@link #v}: 0, or its place in its mesh's one array. */
    private final int at;
    private final Vector3f[] cornerNormals; // null for a flat triangle
    private final Color color;
    private final Material material;

    /** A flat triangle. */
    public Triangle(Vector3f p1, Vector3f p2, Vector3f p3, Color color, Material material) {
        this(p1, p2, p3, null, color, material);
    }

    /**
     * A triangle whose normal at a point is the blend of {@code cornerNormals} (one per corner,
     * any length) by the point's barycentric weights; {@code null} for a flat triangle.
     */
    public Triangle(Vector3f p1, Vector3f p2, Vector3f p3, Vector3f[] cornerNormals, Color color, Material material) {
        this(numbersOf(p1, p2, p3), 0, cornerNormals, color, material);
    }

    /**
     * The triangle whose test numbers {@link #putNumbers} wrote into {@code numbers} from
     * {@code at}, with {@code cornerNormals} as above. A mesh of a million triangles keeps
     * their numbers in a few hundred arrays, shared by thousands of triangles each: the collector
     * copies a few hundred arrays while the mesh is read, instead of a million small ones.
     */
    public Triangle(float[] numbers, int at, Vector3f[] cornerNormals, Color color, Material material) {
        this.v = numbers;
        this.at = at;
        this.cornerNormals = cornerNormals == null ? null : cornerNormals.clone();
        this.color = color;
        this.material = material;
    }

    private static float[] numbersOf(Vector3f p1, Vector3f p2, Vector3f p3) {
        float[] numbers = new float[NUMBERS];
        putNumbers(p1, p2, p3, numbers, 0);
        return numbers;
    }

    /**
     * Writes the {@value #NUMBERS} numbers of the triangle with corners p1, p2, p3 into
     * {@code into} from {@code at}: the corners, the normal n, the per-edge vectors and their
     * lengths, the tolerance, and the sums (see {@link #v}).
     */
    public static void putNumbers(Vector3f p1, Vector3f p2, Vector3f p3, float[] into, int at) {
        Vector3f edge1 = p2.subtract(p1); // each difference once: a mesh makes a million triangles
        Vector3f edge2 = p3.subtract(p2);
        Vector3f edge3 = p1.subtract(p3);
        Vector3f n = edge1.cross(p3.subtract(p1));
        Vector3f in1 = n.cross(edge1);
        Vector3f in2 = n.cross(edge2);
        Vector3f in3 = n.cross(edge3);
        float tolerance = tolerance(thinness(edge1, edge2, edge3, n));
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

    /** Corner {@code i} (0, 1 or 2). */
    public Vector3f corner(int i) {
        return vector(CORNERS + 3 * i);
    }

    /** The unnormalised normal {@code (p2 − p1) × (p3 − p1)}. */
    public Vector3f planeNormal() {
        return vector(NORMAL);
    }

    private static float sum(Vector3f v) {
        return Math.abs(v.x()) + Math.abs(v.y()) + Math.abs(v.z());
    }

    /**
     * How much less certain the normal's direction is than its length suggests, and how thin
     * the triangle is: one over the sine of its smallest angle, {@code |ei||ej| / |n|} at most;
     * about 1 for a well-shaped triangle, large for a needle.
     */
    private static double thinness(Vector3f p1, Vector3f p2, Vector3f p3) {
        return thinness(p2.subtract(p1), p3.subtract(p2), p1.subtract(p3), p2.subtract(p1).cross(p3.subtract(p1)));
    }

    /** {@link #thinness(Vector3f, Vector3f, Vector3f)} from the edges p1 → p2 → p3 → p1 and the normal. */
    private static double thinness(Vector3f edge1, Vector3f edge2, Vector3f edge3, Vector3f normal) {
        double e1 = edge1.magnitude();
        double e2 = edge2.magnitude();
        double e3 = edge3.magnitude();
        double n = normal.magnitude();
        double longest = Math.max(e1 * e2, Math.max(e2 * e3, e3 * e1));
        return n > 0 ? Math.max(1, longest / n) : 1; // never hit if n = 0
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

    /** The {@value #NUMBERS} numbers the test uses, in order, for a packed copy of the test (the BVH's). */
    public float[] testNumbers() {
        return Arrays.copyOfRange(v, at, at + NUMBERS);
    }

    /**
     * Writes the {@value #NUMBERS} numbers of {@link #testNumbers} into {@code into} from
     * {@code at}: the BVH packs a million triangles this way without a copy of each in between.
     */
    public void putTestNumbers(float[] into, int at) {
        System.arraycopy(v, this.at, into, at, NUMBERS);
    }

    /** The normal given for corner {@code i} (0, 1 or 2) of a smooth triangle, or {@code null} for a flat one. */
    public Vector3f cornerNormal(int i) {
        return cornerNormals == null ? null : cornerNormals[i];
    }

    /** Whether the triangle has a normal per corner. */
    public boolean isSmooth() {
        return cornerNormals != null;
    }

    private Vector3f vector(int offset) {
        return new Vector3f(v[at + offset], v[at + offset + 1], v[at + offset + 2]);
    }

    /**
     * The plane's hit {@code t = ((p1 − O)·n) / (R·n)}, then the point {@code P = O + t·R} is
     * inside, or on an edge, when {@code (P − p)·(n × edge) ≥ 0} for each edge from p, up to
     * the rounding of these numbers (see {@link #hit}).
     */
    @Override
    public Intersection intersect(Ray ray) {
        Vector3f o = ray.origin();
        Vector3f d = ray.direction();
        return Intersection.at(ray, hit(v, at, o.x(), o.y(), o.z(), d.x(), d.y(), d.z()));
    }

    /**
     * The test on the {@value #NUMBERS} numbers of {@link #testNumbers}, starting at {@code v[at]}:
     * t of the hit, or NaN. Public for the BVH, which keeps the numbers of many triangles in one
     * array.
     *
     * <p>Each side test allows for its own rounding: a point within a few units of the last
     * place of an edge counts as on it. Without that, a ray through an edge that two triangles
     * of a mesh share could slip between them, as each triangle finds its own P and rounds its
     * own way, and the mesh would show cracks. The allowance has three parts: the rounding of
     * the side test itself ({@code (P − p)} times the normal's uncertainty, larger for a thin
     * triangle), of P's coordinates, and of t along the ray, which grows as the ray comes in
     * flatter, up to {@value #ALONG_THE_RAY} of the distance run.
     */
    public static float hit(float[] v, int at, float ox, float oy, float oz, float dx, float dy, float dz) {
        float facing = (dx * v[at + NORMAL]) + (dy * v[at + NORMAL + 1]) + (dz * v[at + NORMAL + 2]);
        float t = (((v[at] - ox) * v[at + NORMAL]) + ((v[at + 1] - oy) * v[at + NORMAL + 1]) + ((v[at + 2] - oz) * v[at + NORMAL + 2]))
                / facing;
        if (!(t >= 0) || facing == 0 || Float.isInfinite(t)) {
            return Float.NaN;
        }
        float px = ox + dx * t; // as Ray.pointAt rounds it
        float py = oy + dy * t;
        float pz = oz + dz * t;
        float loose = looseness(v, at, px, py, pz, dx, dy, dz, t, facing);
        if (!nearTheCorners(v, at, px, py, pz, loose)) {
            return Float.NaN; // the allowances must not stretch a hit far beyond the corners
        }
        return side(v, at, 0, px, py, pz) >= -allowance(v, at, 0, px, py, pz, loose)
                && side(v, at, 1, px, py, pz) >= -allowance(v, at, 1, px, py, pz, loose)
                && side(v, at, 2, px, py, pz) >= -allowance(v, at, 2, px, py, pz, loose) ? t : Float.NaN;
    }

    /**
     * The part of the side tests' allowance that does not depend on the edge: the rounding of
     * P's coordinates, and of t along the ray, which grows as the ray comes in flatter
     * ({@code |R|·|n| / |R·n|}), up to {@value #ALONG_THE_RAY} of the distance run.
     */
    public static float looseness(float[] v, int at, float px, float py, float pz, float dx, float dy, float dz, float t,
            float facing) {
        float length = Math.abs(dx) + Math.abs(dy) + Math.abs(dz);
        float along = Math.min(ALONG_THE_RAY, 16 * U * (1 + length * v[at + NORMAL_SUM] / Math.abs(facing)));
        return 16 * U * (Math.abs(px) + Math.abs(py) + Math.abs(pz)) + along * t * length;
    }

    /** Whether P lies within the allowances of the corners' box, on every axis. */
    public static boolean nearTheCorners(float[] v, int at, float px, float py, float pz, float loose) {
        float reach = v[at + TOLERANCE] * v[at + SIZE] + loose;
        return near(v, at, 0, px, reach) && near(v, at, 1, py, reach) && near(v, at, 2, pz, reach);
    }

    /**
     * How far below 0 the side test of edge {@code k} (from corner k to the next) may come and
     * still count P as inside: the side test's own rounding, and {@code loose}.
     */
    public static float allowance(float[] v, int at, int k, float px, float py, float pz, float loose) {
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
        return ((px - v[corner]) * v[inward]) + ((py - v[corner + 1]) * v[inward + 1]) + ((pz - v[corner + 2]) * v[inward + 2]);
    }

    /**
     * {@code normalize(n)}, or for a smooth triangle the corners' normals blended by the point's
     * barycentric weights (each corner's weight is the area on the far side of it), normalised.
     */
    @Override
    public Vector3f normalAt(Vector3f point) {
        if (cornerNormals == null) {
            return planeNormal().normalize();
        }
        float w1 = side(v, at, 1, point.x(), point.y(), point.z()); // the edge p2 → p3, opposite p1
        float w2 = side(v, at, 2, point.x(), point.y(), point.z());
        float w3 = side(v, at, 0, point.x(), point.y(), point.z());
        float sum = w1 + w2 + w3;
        Vector3f blend = cornerNormals[0].multiply(w1 / sum).add(cornerNormals[1].multiply(w2 / sum))
                .add(cornerNormals[2].multiply(w3 / sum));
        return blend.normalize();
    }

    /**
     * The corners' box, grown by a few rounding errors of the size and coordinates. The side
     * tests err (and allow) a few units of the last place of the distances involved, except that
     * the normal of a thin triangle, {@code n = e1 × e2}, is as uncertain as {@code |e1||e2|} is
     * large against {@code |n|}: it tilts the side tests by that much more.
     */
    @Override
    public BoundingBox bounds() {
        Vector3f p1 = corner(0);
        Vector3f p2 = corner(1);
        Vector3f p3 = corner(2);
        return BoundingBox.around(margin(p1, p2, p3), p1, p2, p3);
    }

    /** {@link #bounds}, the same numbers, written without making a box. */
    @Override
    public void putBounds(float[] into, int at) {
        BoundingBox.around(margin(corner(0), corner(1), corner(2)), v, this.at + CORNERS, 3, into, at);
    }

    /** How far {@link #bounds} grows the corners' box on every side. */
    private double margin(Vector3f p1, Vector3f p2, Vector3f p3) {
        double e1 = p2.subtract(p1).magnitude();
        double e2 = p3.subtract(p1).magnitude();
        double largest = Math.max(maxAbs(p1), Math.max(maxAbs(p2), maxAbs(p3)));
        // a needle's box may become infinite: then every ray tests it, as the paper's loop does
        double sides = 32 * BoundingBox.UNIT_ROUNDOFF * (e1 + e2) * thinness(p1, p2, p3)
                + 2 * v[at + TOLERANCE] * v[at + SIZE];
        return sides + 64 * BoundingBox.UNIT_ROUNDOFF * (largest + e1 + e2);
    }

    private static double maxAbs(Vector3f p) {
        return Math.max(Math.abs(p.x()), Math.max(Math.abs(p.y()), Math.abs(p.z())));
    }

    /**
     * The plane's t and the hit point err by a few units of the last place of the distance run,
     * and the side tests allow up to {@value #ALONG_THE_RAY} of the distance (summed over the
     * axes, so up to √3 times that).
     */
    @Override
    public Rounding rounding() {
        return Rounding.linear(2 * ALONG_THE_RAY);
    }

    /** The same corners in the same order, whatever its colour, finish and corner normals. */
    @Override
    public Object sameTest() {
        return List.of(corner(0), corner(1), corner(2));
    }

    @Override
    public Color color() {
        return color;
    }

    @Override
    public Material material() {
        return material;
    }

    @Override
    public String kind() {
        return "triangle";
    }
}
