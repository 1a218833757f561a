package rtd.geometry;

import static rtd.geometry.TriangleNumbers.CORNERS;
import static rtd.geometry.TriangleNumbers.NORMAL;
import static rtd.geometry.TriangleNumbers.SIZE;
import static rtd.geometry.TriangleNumbers.TOLERANCE;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A triangle with corners p1, p2, p3 (Part II, "Geometry"): the primitive of rasterisation that
 * the paper names (section 3.3.2), and what a mesh is made of. A triangle of a mesh may carry a
 * normal for each corner, blended across it for smooth shading.
 *
 * <p>This file is the shape: its corners, its normal, its box. The intersection test is
 * {@link RayTriangle}; the numbers it reads, worked out once from the corners and kept as plain
 * floats (a mesh can have millions), are laid out and computed by {@link TriangleNumbers}.
 */
public final class Triangle implements IGeometry {

    /** How many numbers the test uses ({@link #numbers}; their layout: {@link TriangleNumbers}). */
    public static final int NUMBERS = 27;

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
     * The triangle whose test numbers {@link TriangleNumbers#putNumbers} wrote into {@code numbers} from
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
        TriangleNumbers.putNumbers(p1, p2, p3, numbers, 0);
        return numbers;
    }

    /** Corner {@code i} (0, 1 or 2). */
    public Vector3f corner(int i) {
        return vector(CORNERS + 3 * i);
    }

    /** The unnormalised normal {@code (p2 − p1) × (p3 − p1)}. */
    public Vector3f planeNormal() {
        return vector(NORMAL);
    }

    /**
     * The array that holds the {@value #NUMBERS} numbers of this triangle's test from
     * {@link #numbersAt}, in the layout of {@link TriangleNumbers}: its own, or its mesh's, shared
     * by thousands of triangles. The engine runs {@link RayTriangle#hit} on it where it lies, as
     * {@link #intersect} does, so that a mesh's numbers are never copied; it is read, never written.
     */
    public float[] numbers() {
        return v;
    }

    /** Where this triangle's numbers start in {@link #numbers}. */
    public int numbersAt() {
        return at;
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
     * the rounding of these numbers (see {@link RayTriangle#hit}).
     */
    @Override
    public Intersection intersect(Ray ray) {
        return intersect(ray, TestObserver.NONE);
    }

    /** {@link #intersect(Ray)}, telling {@code watch} each number of the test. */
    @Override
    public Intersection intersect(Ray ray, TestObserver watch) {
        Vector3f o = ray.origin();
        Vector3f d = ray.direction();
        return Intersection.at(ray, RayTriangle.hit(v, at, o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), watch));
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
        float[] w = cornerWeights(point);
        Vector3f blend = cornerNormals[0].multiply(w[0]).add(cornerNormals[1].multiply(w[1]))
                .add(cornerNormals[2].multiply(w[2]));
        return blend.normalize();
    }

    /**
     * The barycentric weights of {@code point} in this triangle, one per corner, summing to 1: each
     * the area on the far side of its corner (the edge opposite it, to the point), over the whole.
     * A smooth triangle's normal blends its corners' normals by them; {@code --explain} shows them.
     */
    public float[] cornerWeights(Vector3f point) {
        float w1 = RayTriangle.side(v, at, 1, point.x(), point.y(), point.z()); // the edge p2 → p3, opposite p1
        float w2 = RayTriangle.side(v, at, 2, point.x(), point.y(), point.z());
        float w3 = RayTriangle.side(v, at, 0, point.x(), point.y(), point.z());
        float sum = w1 + w2 + w3;
        return new float[] {w1 / sum, w2 / sum, w3 / sum};
    }

    /**
     * The corners' box, grown by a few rounding errors of the size and coordinates. The side
     * tests err (and allow) a few units of the last place of the distances involved, except that
     * the normal of a thin triangle, {@code n = e1 × e2}, is as uncertain as {@code |e1||e2|} is
     * large against {@code |n|}: it tilts the side tests by that much more.
     */
    @Override
    public BoundingBox bounds() {
        float[] box = new float[6];
        putBounds(box, 0);
        return new BoundingBox(new Vector3f(box[0], box[1], box[2]), new Vector3f(box[3], box[4], box[5]));
    }

    /**
     * Writes {@link #bounds} to {@code into[at .. at+5]} as {@link BoundingBox#put} does, with no
     * object made: the engine measures a mesh's million triangles this way.
     */
    public void putBounds(float[] into, int at) {
        BoundingBox.putAround(margin(), v, this.at + CORNERS, 3, into, at);
    }

    /** How far {@link #bounds} grows the corners' box on every side. */
    private double margin() {
        int p1 = at + CORNERS;
        double e1 = TriangleNumbers.distance(v, p1, p1 + 3);
        double e2 = TriangleNumbers.distance(v, p1, p1 + 6);
        double largest = 0;
        for (int k = p1; k < p1 + 9; k++) {
            largest = Math.max(largest, Math.abs(v[k]));
        }
        // a needle's box may become infinite: then every ray tests it, as the paper's loop does
        double sides = 32 * BoundingBox.UNIT_ROUNDOFF * (e1 + e2) * TriangleNumbers.thinness(v, at)
                + 2 * v[at + TOLERANCE] * v[at + SIZE];
        return sides + 64 * BoundingBox.UNIT_ROUNDOFF * (largest + e1 + e2);
    }

    @Override
    public Color color() {
        return color;
    }

    @Override
    public Material material() {
        return material;
    }

    /** A surface, not a solid: a ray that meets it from behind meets its back. */
    @Override
    public boolean isSolid() {
        return false;
    }

    @Override
    public String kind() {
        return "triangle";
    }
}
