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
}
