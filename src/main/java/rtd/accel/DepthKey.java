package rtd.accel;

/**
 * The paper's depth test (Listing 4.3) as one number: the nearest hit wins, and on a tie the
 * object that comes first in the file. Both tracers that keep a nearest hit compare these keys
 * ({@link NearestHit} for one ray, {@link TileOfHits} for a tile of pixels), so that they agree
 * with the loop and with each other, whatever the order of their tests.
 */
final class DepthKey {

    /** The key that no hit beats: an infinite distance ties with it at best, and loses. */
    static final long NONE = of(Float.POSITIVE_INFINITY, 0);

    private DepthKey() {
    }

    /**
     * The depth test's order as one number, smaller wins: the distance, then the place in the
     * file. The bits of a float {@code ≥ 0} order as its values do, so they go first; the place
     * breaks ties. A distance is never negative, so its sign bit is cleared: a NaN distance
     * (0 · ∞, a hit at t = ∞ on a ray with a zero component) made at run time may carry the sign,
     * and must sort above +∞ ({@link #NONE}), never winning, as {@code distance < nearest} never
     * lets it in the paper's loop. One comparison instead of two also keeps the JIT from compiling
     * the hot loop anew the first time two objects tie.
     */
    static long of(float distance, int index) {
        return ((long) (Float.floatToRawIntBits(distance) & 0x7FFF_FFFF) << 32) | index;
    }
}
