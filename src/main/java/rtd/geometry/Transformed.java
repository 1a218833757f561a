package rtd.geometry;

import rtd.image.Color;
import rtd.math.Matrix4;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A shape moved, turned or stretched by a transformation M (<i>The Ray Tracer Challenge</i>,
 * chapters 4 and 14): a scaled sphere is an ellipsoid, a rotated box a tilted box.
 *
 * <p>Nothing of the shape changes. Its test runs on the ray taken into the shape's own space,
 * {@code M⁻¹O + t·M⁻¹R} (the direction not normalised, so that t is the same on both rays), and
 * the hit point is {@code P = O + t·R} of the world's ray, so the depth test compares world
 * distances. The normal is {@code normalize((M⁻¹)ᵀ·n)} of the shape's normal n, the box the box
 * around the shape's box's eight corners, transformed (an unbounded shape stays unbounded). The
 * engine does not know this kind, and tests it through {@link #intersect}: the shape's own test.
 */
public final class Transformed implements IGeometry {

    private final IGeometry shape;
    private final Matrix4 matrix;
    private final Matrix4 inverse;
    private final BoundingBox bounds;

    /** {@code shape} transformed by {@code matrix}, whose determinant is not 0. */
    public Transformed(IGeometry shape, Matrix4 matrix) {
        this.shape = shape;
        this.matrix = matrix;
        this.inverse = matrix.inverse();
        this.bounds = transformedBox(shape.bounds(), matrix);
    }

    /** The shape in its own space. */
    public IGeometry shape() {
        return shape;
    }

    /** M, which takes the shape's space to the world's. */
    public Matrix4 matrix() {
        return matrix;
    }

    @Override
    public Intersection intersect(Ray ray) {
        return intersect(ray, TestObserver.NONE);
    }

    /**
     * The shape's own test on the ray in its space; the hit point on the world's ray at the same t. A hit
     * outside the object's box is no hit: float rounding of a ray from far away, magnified by an uneven
     * scale, would put it there, and it is noise, not the surface. So every hit lies in {@link #bounds},
     * as the engine requires of a shape it does not know.
     */
    @Override
    public Intersection intersect(Ray ray, TestObserver watch) {
        Ray local = objectRay(ray);
        watch.transformedRay(matrix, local);
        Intersection hit = Intersection.at(ray, shape.intersect(local, watch).t());
        if (!hit.happened() || inBounds(hit)) {
            return hit;
        }
        watch.outsideBox(hit.t());
        return Intersection.at(ray, Float.NaN);
    }

    private boolean inBounds(Intersection hit) {
        Vector3f min = bounds.min();
        Vector3f max = bounds.max();
        return min.x() <= hit.x() && hit.x() <= max.x() && min.y() <= hit.y() && hit.y() <= max.y()
                && min.z() <= hit.z() && hit.z() <= max.z(); // true throughout for an unbounded shape
    }

    /** {@code M⁻¹O + t·M⁻¹R}: the ray in the shape's space. */
    public Ray objectRay(Ray ray) {
        return new Ray(inverse.point(ray.origin()), inverse.direction(ray.direction()));
    }

    @Override
    public Vector3f normalAt(Vector3f point) {
        return world(shape.normalAt(inverse.point(point)));
    }

    @Override
    public Vector3f normalAt(Vector3f point, Vector3f direction) {
        return world(shape.normalAt(inverse.point(point), inverse.direction(direction)));
    }

    /** {@code normalize((M⁻¹)ᵀ·n)}: a normal of the shape, in the world. */
    private Vector3f world(Vector3f normal) {
        return inverse.transposeDirection(normal).normalize();
    }

    @Override
    public BoundingBox bounds() {
        return bounds;
    }

    @Override
    public Color color() {
        return shape.color();
    }

    @Override
    public boolean isPatterned() {
        return shape.isPatterned();
    }

    /** The shape's colour at {@code under} taken into its space ({@code M⁻¹·under}). */
    @Override
    public Color colorAt(Vector3f under, PatternObserver watch) {
        return shape.colorAt(inverse.point(under), watch);
    }

    @Override
    public Material material() {
        return shape.material();
    }

    @Override
    public boolean isSolid() {
        return shape.isSolid();
    }

    @Override
    public String kind() {
        return shape.kind();
    }

    /** The box around {@code box}'s eight corners transformed by {@code m}, rounded outwards; unbounded stays so. */
    static BoundingBox transformedBox(BoundingBox box, Matrix4 m) {
        if (!box.isBounded()) {
            return BoundingBox.UNBOUNDED;
        }
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double[] corner = new double[3];
        for (int i = 0; i < 8; i++) {
            m.point((i & 1) == 0 ? box.min().x() : box.max().x(), (i & 2) == 0 ? box.min().y() : box.max().y(),
                    (i & 4) == 0 ? box.min().z() : box.max().z(), corner);
            for (int k = 0; k < 3; k++) {
                lo[k] = Math.min(lo[k], corner[k]);
                hi[k] = Math.max(hi[k], corner[k]);
            }
        }
        return BoundingBox.around(0, new Vector3f(Math.nextDown((float) lo[0]), Math.nextDown((float) lo[1]),
                Math.nextDown((float) lo[2])), new Vector3f(Math.nextUp((float) hi[0]), Math.nextUp((float) hi[1]),
                Math.nextUp((float) hi[2])));
    }
}
