package rtd.geometry;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A geometric object of a scene (paper, section 4.2.2).
 *
 * <p>Each kind of object knows how to test itself against a ray, because that test differs
 * from shape to shape; the depth test that compares objects lives above, in {@code rtd.scene.Scene.nearestHit} (the
 * paper's loop) and {@code rtd.accel.NearestHit} (the hierarchy's and the view grid's).
 * A new shape implements this interface: its test, its normal, its box, its colour and finish.
 * The paper has spheres; Part II adds planes, triangles, boxes and (as triangles) meshes.
 */
public interface IGeometry {

    /**
     * How far a float intersection test may report a hit away from its object at most,
     * relative to the distance the ray has run: the widest cone of {@link #bounds}' contract.
     */
    float ROUNDING_CONE = 1.1e-3f;

    /**
     * The intersection test (section 3.2.2): where, if anywhere, the ray hits this object at
     * some {@code t ≥ 0}. A ray that starts inside a closed object hits its far side. Return
     * {@code Intersection.at(ray, t)} (NaN: no hit): the hierarchy finds the hit point from t the
     * same way, and the two must agree to the last bit.
     */
    Intersection intersect(Ray ray);

    /**
     * {@link #intersect(Ray)}, telling {@code watch} the numbers of the test as it computes them
     * ({@code --explain}). A shape that does not override it tells nothing.
     */
    default Intersection intersect(Ray ray, TestObserver watch) {
        return intersect(ray);
    }

    /** The outward unit normal at {@code point}, a point of the surface (a hit point). */
    Vector3f normalAt(Vector3f point);

    /**
     * An axis-aligned box around the object for a bounding volume hierarchy, or
     * {@link BoundingBox#UNBOUNDED} for an object without limits.
     *
     * <p>It must hold every hit that {@link #intersect} can report, including those that
     * single-precision rounding adds near the surface, up to a margin that grows with the
     * distance {@code L = t·|R|} the ray has run to the hit: for any ray {@code O + t·R}, a
     * reported hit at t lies in the box grown on every side by {@link #rounding}'s
     * {@code linear·L + min(ROUNDING_CONE·L, quadratic·L²)}. The box does not depend on a
     * camera, so the hierarchy finds the loop's hit for rays from anywhere.
     */
    BoundingBox bounds();

    /**
     * Writes {@link #bounds} to {@code into[at .. at+5]}: min x, y, z, max x, y, z. A shape of
     * which scenes hold millions (spheres) writes the same numbers without making a box, so that
     * the hierarchy measures its objects without garbage.
     */
    default void putBounds(float[] into, int at) {
        bounds().put(into, at);
    }

    /**
     * How fast the rounding of {@link #intersect} lets a reported hit stray from the object's
     * box as the ray runs farther (see {@link #bounds}). By default the widest cone; a shape
     * whose test rounds less says so, and its boxes grow less in the hierarchy.
     */
    default Rounding rounding() {
        return Rounding.WIDEST;
    }

    /**
     * The lengths {@code |R|₁} of the directions {@link #roundingFrom} speaks of: a camera's rays
     * are about its focal length in pixels long. Far beyond these, a test's float products may
     * overflow or fall among the subnormal numbers, and its rounding is another matter.
     */
    double SHORTEST_DIRECTION = 1e-10;
    /** See {@link #SHORTEST_DIRECTION}. */
    double LONGEST_DIRECTION = 1e20;

    /**
     * {@link #rounding} for the rays that leave one point, {@code origin} (a perspective camera's
     * eye), with a direction R of {@link #SHORTEST_DIRECTION} ≤ |R|₁ ≤ {@link #LONGEST_DIRECTION},
     * for this object whose {@link #putBounds} are {@code box[at .. at+5]}: a hit that such a ray
     * reports lies in that box grown by it, as {@link #bounds} says. Never more than
     * {@link #rounding}, and by default the same; a triangle's test errs less for a ray that meets
     * it steeply, and the rays from one point meet it within a range of angles
     * ({@link RayTriangle#alongTheRayFrom}).
     */
    default Rounding roundingFrom(Vector3f origin, float[] box, int at) {
        return rounding();
    }

    /** The flat colour the object paints the pixels whose ray it is nearest on. */
    Color color();

    /** The object's finish, for shading. */
    Material material();

    /**
     * A value that equals another object's exactly when the two report the same hit, to the
     * last bit, for every ray: the same shape in the same place. The accelerator keeps only the
     * first of such twins, which wins every tie. By default an object is its own and only twin.
     */
    default Object sameTest() {
        return this;
    }

    /**
     * Whether the shape encloses a volume (a sphere, a box), so that a ray can be inside it; a
     * plane or a triangle is a surface, and a ray that meets it from behind meets its back. The
     * shading treats both alike (the back of a surface counts as its inside, for refraction too);
     * {@code --explain} says which.
     */
    default boolean isSolid() {
        return true;
    }

    /**
     * The kind of object, as the scene file names it ("sphere", "plane", ...): its name in
     * {@code --stats}, {@code --explain}, the {@code --view id} legend and the messages; the
     * accelerators also group objects of one kind for their packed tests.
     */
    String kind();
}
