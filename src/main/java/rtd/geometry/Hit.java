package rtd.geometry;

import rtd.image.Color;
import rtd.math.Vector3f;

/**
 * What a ray hits: the answer of the nearest-hit query (the depth test of section 3.2.3,
 * Listing 4.3) for any ray, a camera's or not.
 *
 * <p>It holds what every candidate's test already computed (t, the hit point, the distance the
 * depth test compares). The surface normal is computed only on request, for the one object that
 * won: most objects a ray tests lose the depth test, and their normals would be wasted work.
 *
 * @param object   the object hit
 * @param index    its place among the scene's objects, in file order (which wins a tie)
 * @param t        the ray parameter of the hit point, {@code P = O + t·R}
 * @param distance the depth test's {@code |P − O|}
 * @param point    the hit point P, as the intersection test computed it
 */
public record Hit(IGeometry object, int index, float t, float distance, Vector3f point) {

    /** ε per unit of the hit point's largest coordinate: how far points lifted off a surface lie from it. */
    private static final float LIFT = 1e-4f;

    /** The object's outward unit normal at the hit point of a ray along {@code direction}. */
    public Vector3f normal(Vector3f direction) {
        return object.normalAt(point, direction);
    }

    /**
     * How far points just off the surface lie from the hit point P: {@code ε = 1e-4·(1 + max(|Px|,
     * |Py|, |Pz|))}, so that it stays above float's rounding of P however far P is from the origin.
     */
    public float lift() {
        return LIFT * (1 + Math.max(Math.abs(point.x()), Math.max(Math.abs(point.y()), Math.abs(point.z()))));
    }

    /**
     * The colour the object shows at this hit of a ray along {@code direction}: its flat colour,
     * or for a patterned object its pattern's colour at {@code P − ε·N}, N the normal turned
     * towards the ray's origin (as shading turns it), so that a surface lying on a pattern's
     * boundary shows the side beneath it, not noise.
     */
    public Color colour(Vector3f direction) {
        return colour(direction, PatternObserver.NONE);
    }

    /** {@link #colour(Vector3f)}, telling {@code watch} how a pattern chose it ({@code --explain}). */
    public Color colour(Vector3f direction, PatternObserver watch) {
        return object.isPatterned() ? object.colorAt(under(direction, normal(direction)), watch) : object.color();
    }

    /** {@code P − ε·N}, N being {@code normal} turned towards where the ray along {@code direction} came from. */
    public Vector3f under(Vector3f direction, Vector3f normal) {
        Vector3f eye = direction.normalize().inverse();
        Vector3f towardsEye = normal.dot(eye) < 0 ? normal.inverse() : normal;
        return point.subtract(towardsEye.multiply(lift()));
    }
}
