package rtd.geometry;

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

    private final float[] v; // p1, p2, p3, n = (p2 − p1) × (p3 − p1), and n × edge for the three edges
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
        Vector3f n = p2.subtract(p1).cross(p3.subtract(p1));
        Vector3f in1 = n.cross(p2.subtract(p1));
        Vector3f in2 = n.cross(p3.subtract(p2));
        Vector3f in3 = n.cross(p1.subtract(p3));
        this.v = new float[] {p1.x(), p1.y(), p1.z(), p2.x(), p2.y(), p2.z(), p3.x(), p3.y(), p3.z(),
            n.x(), n.y(), n.z(), in1.x(), in1.y(), in1.z(), in2.x(), in2.y(), in2.z(), in3.x(), in3.y(), in3.z()};
        this.cornerNormals = cornerNormals == null ? null : cornerNormals.clone();
        this.color = color;
        this.material = material;
    }

    /** Corner {@code i} (0, 1 or 2). */
    public Vector3f corner(int i) {
        return vector(3 * i);
    }

    /** The unnormalised normal {@code (p2 − p1) × (p3 − p1)}. */
    public Vector3f planeNormal() {
        return vector(9);
    }

    /** The 21 numbers the test uses, in order, for a packed copy of the test (the BVH's). */
    public float[] testNumbers() {
        return v.clone();
    }

    /** The normal given for corner {@code i} (0, 1 or 2) of a smooth triangle, or {@code null} for a flat one. */
    public Vector3f cornerNormal(int i) {
        return cornerNormals == null ? null : cornerNormals[i];
    }

    /** Whether the triangle has a normal per corner. */
    public boolean isSmooth() {
        return cornerNormals != null;
    }

    private Vector3f vector(int at) {
        return new Vector3f(v[at], v[at + 1], v[at + 2]);
    }

    /**
     * The plane's hit {@code t = ((p1 − O)·n) / (R·n)}, then the point {@code P = O + t·R} is
     * inside, or on an edge, when {@code (P − p)·(n × edge) ≥ 0} for each edge from p.
     */
    @Override
    public Intersection intersect(Ray ray) {
        Vector3f o = ray.origin();
        Vector3f d = ray.direction();
        return Intersection.at(ray, hit(v, 0, o.x(), o.y(), o.z(), d.x(), d.y(), d.z()));
    }

    /**
     * The test on the 21 numbers of {@link #testNumbers}, starting at {@code v[at]}: t of the hit,
     * or NaN. Public for the BVH, which keeps the numbers of many triangles in one array.
     */
    public static float hit(float[] v, int at, float ox, float oy, float oz, float dx, float dy, float dz) {
        float facing = (dx * v[at + 9]) + (dy * v[at + 10]) + (dz * v[at + 11]);
        float t = (((v[at] - ox) * v[at + 9]) + ((v[at + 1] - oy) * v[at + 10]) + ((v[at + 2] - oz) * v[at + 11])) / facing;
        if (!(t >= 0) || facing == 0 || Float.isInfinite(t)) {
            return Float.NaN;
        }
        float px = ox + dx * t; // as Ray.pointAt rounds it
        float py = oy + dy * t;
        float pz = oz + dz * t;
        return side(v, at, at + 12, px, py, pz) >= 0 && side(v, at + 3, at + 15, px, py, pz) >= 0
                && side(v, at + 6, at + 18, px, py, pz) >= 0 ? t : Float.NaN;
    }

    /** {@code (P − corner)·inward}: ≥ 0 when P lies on the triangle's side of the edge from that corner. */
    private static float side(float[] v, int corner, int inward, float px, float py, float pz) {
        return ((px - v[corner]) * v[inward]) + ((py - v[corner + 1]) * v[inward + 1]) + ((pz - v[corner + 2]) * v[inward + 2]);
    }

    /**
     * {@code normalize(n)}, or for a smooth triangle the corners' normals blended by the point's
     * barycentric weights (each corner's weight is the area on the far side of it), normalised.
     */
    @Override
    public Vector3f normalAt(Vector3f point) {
        Vector3f n = planeNormal().normalize();
        if (cornerNormals == null) {
            return n;
        }
        float w1 = side(v, 3, 15, point.x(), point.y(), point.z()); // the edge p2 → p3, opposite p1
        float w2 = side(v, 6, 18, point.x(), point.y(), point.z());
        float w3 = side(v, 0, 12, point.x(), point.y(), point.z());
        float sum = w1 + w2 + w3;
        Vector3f blend = cornerNormals[0].multiply(w1 / sum).add(cornerNormals[1].multiply(w2 / sum))
                .add(cornerNormals[2].multiply(w3 / sum));
        return blend.normalize();
    }

    /**
     * The corners' box, grown by a few rounding errors of the size and coordinates. The side
     * tests err by a few units of the last place of the distances involved, except that the
     * normal of a thin triangle, {@code n = e1 × e2}, is as uncertain as {@code |e1||e2|} is
     * large against {@code |n|}: it tilts the side tests by that much more.
     */
    @Override
    public BoundingBox bounds() {
        Vector3f p1 = corner(0);
        Vector3f p2 = corner(1);
        Vector3f p3 = corner(2);
        double e1 = p2.subtract(p1).magnitude();
        double e2 = p3.subtract(p1).magnitude();
        double n = planeNormal().magnitude();
        double thinness = n > 0 ? e1 * e2 / n : 1; // never hit if n = 0; so thin a box may become infinite, and be tested by every ray
        return BoundingBox.around(32 * BoundingBox.UNIT_ROUNDOFF * (e1 + e2) * thinness, p1, p2, p3);
    }

    /** The plane's t and the hit point err by a few units of the last place of the distance run. */
    @Override
    public Rounding rounding() {
        return Rounding.linear(1e-5f);
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
