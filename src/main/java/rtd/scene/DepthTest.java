package rtd.scene;

import rtd.math.Vector3f;

/**
 * The depth test (section 3.2.3, Listing 4.3): of the objects a ray hits, the one whose hit
 * point P lies nearest to the ray's origin O wins, and on a tie the one that comes first in the
 * scene file. Written once, here: the paper's loop ({@link Scene#nearestHit}), the accelerators
 * and {@code --explain} all compare hits with it, so they agree whatever order they test in.
 */
public final class DepthTest {

    /** The key that no hit beats: {@link #key} of an infinite distance ties with it at best, and loses. */
    public static final long NO_HIT = key(Float.POSITIVE_INFINITY, 0);

    private DepthTest() {
    }

    /** {@code |P − O|} (Listing 4.3, lines 4 to 6): how far the hit point P lies from the ray's origin O. */
    public static float distance(Vector3f p, Vector3f o) {
        return distance(p.x(), p.y(), p.z(), o.x(), o.y(), o.z());
    }

    /** {@link #distance(Vector3f, Vector3f)} on numbers. */
    public static float distance(float px, float py, float pz, float ox, float oy, float oz) {
        float x = px - ox;
        float y = py - oy;
        float z = pz - oz;
        return (float) Math.sqrt(x * x + y * y + z * z);
    }

    /**
     * Whether a hit at {@code distance} on object number {@code index} (its place in the file)
     * beats the nearest so far, at {@code nearestDistance} on object {@code nearestIndex}
     * (Listing 4.3, line 7).
     */
    public static boolean nearer(float distance, int index, float nearestDistance, int nearestIndex) {
        return key(distance, index) < key(nearestDistance, nearestIndex);
    }

    /**
     * The depth test's order as one number, smaller wins: the distance, then the place in the
     * file. The bits of a float {@code ≥ 0} order as its values do, so they go first; the place
     * breaks ties. The sign bit is cleared: a NaN distance (0 · ∞, a hit at t = ∞ on a ray with a
     * zero component) may carry it, and must sort above +∞ ({@link #NO_HIT}), never winning. A
     * tracer that keeps its nearest hit as a key compares one number per hit.
     */
    public static long key(float distance, int index) {
        return ((long) (Float.floatToRawIntBits(distance) & 0x7FFF_FFFF) << 32) | (index & 0xFFFF_FFFFL);
    }
}
