package rtd.geometry;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A geometric object of a scene (paper, section 4.2.2).
 *
 * <p>Each kind of object knows how to test itself against a ray, because that test differs
 * from shape to shape; the depth test that compares objects lives above
 * ({@code rtd.scene.DepthTest}). A new shape implements this interface: its test, its normal,
 * its box, its colour and finish; every renderer then draws it.
 * The paper has spheres; Part II adds planes, triangles, boxes and (as triangles) meshes.
 */
public interface IGeometry {

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
     * The outward unit normal where a ray running along {@code direction} hits the surface at
     * {@code point}: {@link #normalAt(Vector3f)}. A shape with edges overrides it to say which
     * face a hit on an edge belongs to: the one the ray crosses there, never a face the ray runs
     * along.
     */
    default Vector3f normalAt(Vector3f point, Vector3f direction) {
        return normalAt(point);
    }

    /**
     * An axis-aligned box around the object, or {@link BoundingBox#UNBOUNDED} for an object
     * without limits. It must hold every hit {@link #intersect} can report (the engine grows it a
     * little for the rounding of float tests), and it does not depend on a camera: the engine
     * finds the loop's hit for rays from anywhere.
     */
    BoundingBox bounds();

    /** The flat colour the object paints the pixels whose ray it is nearest on. */
    Color color();

    /**
     * Whether the object's colour changes from point to point (it shows a {@link Pattern}); if
     * not, {@link #color()} is its colour everywhere and {@link #colorAt} need not be asked.
     */
    default boolean isPatterned() {
        return false;
    }

    /**
     * The colour at {@code under}, the point just beneath the surface where a ray hit it
     * ({@link Hit#colour}): {@link #color()} unless the object is patterned.
     */
    default Color colorAt(Vector3f under) {
        return colorAt(under, PatternObserver.NONE);
    }

    /** {@link #colorAt(Vector3f)}, telling {@code watch} how a pattern chose the colour ({@code --explain}). */
    default Color colorAt(Vector3f under, PatternObserver watch) {
        return color();
    }

    /** The object's finish, for shading. */
    Material material();

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
     * {@code --stats}, {@code --explain}, the {@code --view id} legend and the messages.
     */
    String kind();
}
