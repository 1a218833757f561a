package rtd.camera;

import rtd.math.Vector3f;

/**
 * Rays that all run along one {@code direction} from origins inside the box from
 * {@code lowestOrigin} to {@code highestOrigin}: the rays of a square of pixels of a parallel
 * projection such as the paper's orthographic camera (section 3.2.1). Not in the paper: a
 * bounding volume hierarchy uses it to find, once for the whole square, which objects its rays
 * can reach ({@link rtd.accel.BvhTracer}).
 *
 * @param lowestOrigin  the smallest x, y and z of any origin
 * @param highestOrigin the largest x, y and z of any origin
 * @param direction     the direction every ray has, exactly
 */
public record Beam(Vector3f lowestOrigin, Vector3f highestOrigin, Vector3f direction) {

    /**
     * The beam along {@code direction} whose box just holds {@code origins}; {@code null} if
     * there are none, or if one is not finite (then float cannot hold the beam's size).
     */
    public static Beam around(Vector3f direction, Vector3f... origins) {
        if (origins.length == 0) {
            return null;
        }
        Vector3f lowest = origins[0];
        Vector3f highest = origins[0];
        for (Vector3f origin : origins) {
            if (!origin.isFinite()) {
                return null;
            }
            lowest = new Vector3f(Math.min(lowest.x(), origin.x()), Math.min(lowest.y(), origin.y()),
                    Math.min(lowest.z(), origin.z()));
            highest = new Vector3f(Math.max(highest.x(), origin.x()), Math.max(highest.y(), origin.y()),
                    Math.max(highest.z(), origin.z()));
        }
        return new Beam(lowest, highest, direction);
    }
}
