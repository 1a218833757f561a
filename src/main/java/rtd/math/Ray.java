package rtd.math;

/**
 * A ray: a half-line that starts at {@code origin} (O) and runs along {@code direction} (R)
 * (paper, section 3.2.1, equation 3.1).
 *
 * <p>The points of the ray are {@code P = O + t·R} for {@code t ≥ 0}. The direction need not
 * have length 1; the orthographic camera passes its view direction on exactly as given.
 */
public record Ray(Vector3f origin, Vector3f direction) {

    /** Returns the point {@code O + t·R} of equation 3.1. */
    public Vector3f pointAt(float t) {
        return origin.add(direction.multiply(t));
    }
}
