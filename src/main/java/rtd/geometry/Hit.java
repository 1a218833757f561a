package rtd.geometry;

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

    /** The object's outward unit normal at the hit point of a ray along {@code direction}. */
    public Vector3f normal(Vector3f direction) {
        return object.normalAt(point, direction);
    }
}
