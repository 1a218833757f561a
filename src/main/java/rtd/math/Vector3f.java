package rtd.math;

/**
 * A point or a vector in space, with three {@code float} coordinates (paper, section 4.2.1).
 *
 * <p>As in the paper, one type stands for both: {@code (x|y|z)} is either the point P or the
 * vector from the origin to P. The operations are those of Listing B.1. Each returns a new
 * vector; a {@code Vector3f} never changes.
 */
public record Vector3f(float x, float y, float z) {

    /** The zero vector. */
    public static final Vector3f ZERO = new Vector3f(0, 0, 0);

    /** Returns {@code this + other}. */
    public Vector3f add(Vector3f other) {
        return new Vector3f(x + other.x, y + other.y, z + other.z);
    }

    /** Returns {@code this - other}: for two points, the vector from {@code other} to {@code this}. */
    public Vector3f subtract(Vector3f other) {
        return new Vector3f(x - other.x, y - other.y, z - other.z);
    }

    /** Returns this vector scaled by {@code factor}. */
    public Vector3f multiply(float factor) {
        return new Vector3f(x * factor, y * factor, z * factor);
    }

    /** Returns this vector divided by {@code divisor}. */
    public Vector3f divide(float divisor) {
        return new Vector3f(x / divisor, y / divisor, z / divisor);
    }

    /** Returns the dot (scalar) product, summed left to right as in Listing B.1. */
    public float dot(Vector3f other) {
        return (x * other.x) + (y * other.y) + (z * other.z);
    }

    /** Returns the cross product {@code this × other}, a vector perpendicular to both. */
    public Vector3f cross(Vector3f other) {
        return new Vector3f(
                y * other.z - z * other.y,
                z * other.x - x * other.z,
                x * other.y - y * other.x);
    }

    /** Returns the length of this vector. */
    public float magnitude() {
        return (float) Math.sqrt(x * x + y * y + z * z);
    }

    /** Returns the vector of length 1 that points the same way; NaN for the zero vector. */
    public Vector3f normalize() {
        return divide(magnitude());
    }

    /** Returns the vector that points the opposite way. */
    public Vector3f inverse() {
        return new Vector3f(-x, -y, -z);
    }

    /** Whether all three coordinates are finite (neither NaN nor infinite). */
    public boolean isFinite() {
        return Float.isFinite(x) && Float.isFinite(y) && Float.isFinite(z);
    }

    @Override
    public String toString() {
        return "(" + x + "|" + y + "|" + z + ")";
    }
}
