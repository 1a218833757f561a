package rtd.geometry;

import rtd.math.Vector3f;

/**
 * An axis-aligned box, given by its lowest and highest corner. A bounding volume hierarchy
 * ({@link rtd.accel.Bvh}) sorts objects into a tree of such boxes.
 */
public record BoundingBox(Vector3f min, Vector3f max) {

    /** The box's centre, by which the hierarchy sorts the objects. */
    public Vector3f centre() {
        return min.add(max).multiply(0.5f);
    }
}
