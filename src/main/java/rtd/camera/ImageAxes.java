package rtd.camera;

import rtd.math.Vector3f;

/**
 * The image's axes in the world, as Listing 4.1 makes them from the view direction:
 * {@code u = normalize(dir × (0,1,0))} points right in the image, {@code v = normalize(dir × u)}
 * points down. Both cameras use them.
 *
 * <p>Looking straight up or down, {@code dir × (0,1,0)} is zero and gives no right axis. Then
 * world x points right, as it does for the default view along −z: it is the limit of tilting
 * that view down (or up) to vertical, so the picture does not jump.
 *
 * @param u the right axis (the paper's {@code widthVector})
 * @param v the down axis (the paper's {@code heightVector})
 */
public record ImageAxes(Vector3f u, Vector3f v) {

    private static final Vector3f WORLD_UP = new Vector3f(0, 1, 0);
    private static final Vector3f WORLD_RIGHT = new Vector3f(1, 0, 0);

    /** The axes for the view direction {@code dir} (any length, not zero). */
    public static ImageAxes of(Vector3f dir) {
        Vector3f u = looksStraightUpOrDown(dir) ? WORLD_RIGHT : dir.cross(WORLD_UP).normalize();
        return new ImageAxes(u, dir.cross(u).normalize());
    }

    /** Whether {@code dir × (0,1,0)} gives no right axis (it is zero, or too short for float): then x is right. */
    public static boolean looksStraightUpOrDown(Vector3f dir) {
        Vector3f right = dir.cross(WORLD_UP);
        return !(right.magnitude() > 0 && right.normalize().isFinite());
    }
}
