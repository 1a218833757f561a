package rtd.camera;

import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The paper's camera: an orthographic (parallel) projection (section 3.2.1, Listing 4.1).
 *
 * <p>All rays share the view direction; their origins lie on a plane through the camera's
 * position, spread out along two image axes: {@code widthVector} (u) points right in the
 * image and {@code heightVector} (v) points down. {@code zoom} is how many pixels one world
 * unit covers.
 */
public final class OrthographicCamera implements ICamera {

    private static final Vector3f WORLD_UP = new Vector3f(0, 1, 0);
    /** The right axis used when the view direction is parallel to {@link #WORLD_UP}. */
    private static final Vector3f WORLD_RIGHT = new Vector3f(1, 0, 0);

    private final Vector3f pos;
    private final Vector3f dir;
    private final float zoom;
    private final Vector3f widthVector;
    private final Vector3f heightVector;
    /** |dir| and |pos|, kept for {@link #farthestOrigin}, which the BVH asks once per object. */
    private final double dirLength;
    private final double posLength;

    /**
     * Makes a camera at {@code pos} that looks along {@code dir} (any non-zero length) and
     * shows {@code zoom} pixels per world unit.
     */
    public OrthographicCamera(Vector3f pos, Vector3f dir, float zoom) {
        this.pos = pos;
        this.dir = dir;
        this.zoom = zoom;
        this.widthVector = widthVector(dir);
        this.heightVector = dir.cross(widthVector).normalize();
        this.dirLength = dir.magnitude();
        this.posLength = pos.magnitude();
    }

    /**
     * The image's right axis u = normalize(dir × (0,1,0)) of Listing 4.1.
     *
     * <p>Looking straight up or down, {@code dir × (0,1,0)} is zero and gives no right axis.
     * Then world x points right, as it does for the default view along −z: it is the limit
     * of tilting that view down (or up) to vertical, so the picture does not jump.
     */
    private static Vector3f widthVector(Vector3f dir) {
        Vector3f right = dir.cross(WORLD_UP);
        return right.magnitude() > 0 && right.normalize().isFinite() ? right.normalize() : WORLD_RIGHT;
    }

    /**
     * Listing 4.1: the pixel's offset from the image centre (integer division, so each ray
     * leaves the pixel's corner) moves the origin along u and v; the direction stays
     * {@code dir}. The operations run in the paper's order, for the same rounding.
     */
    @Override
    public Ray generateRay(int x, int y, int w, int h) {
        int offsetX = x - (w / 2);
        int offsetY = y - (h / 2);
        Vector3f origin = pos.add(widthVector.multiply(offsetX).divide(zoom)
                .add(heightVector.multiply(offsetY).divide(zoom)));
        return new Ray(origin, dir);
    }

    @Override
    public Vector3f position() {
        return pos;
    }

    /**
     * All origins lie in the plane through {@code pos} perpendicular to {@code dir}, so a ray
     * that passes within {@code reach} of the point starts at most
     * {@code √(depth² + reach²)} from it, where depth is the point's distance from that plane.
     * A small relative margin covers the rounding of the origins.
     */
    @Override
    public float farthestOrigin(Vector3f point, float reach) {
        double depth = Math.abs(point.subtract(pos).dot(dir)) / dirLength;
        double distance = Math.sqrt(depth * depth + (double) reach * reach); // float's range squared fits a double
        return (float) (distance * (1 + 1e-6) + 1e-6 * posLength);
    }

    /**
     * All rays share {@code dir}, and the four corner pixels' origins bound every origin in
     * between. Why the corners suffice, even with rounding: in {@link #generateRay} each
     * coordinate of the origin is made from the pixel's x by a product, a quotient by
     * {@code zoom > 0} and two sums, and from y likewise. Each of these is monotonic in its
     * input, and rounding to nearest keeps it monotonic, so each coordinate only grows (or only
     * shrinks) as x grows, and as y grows: its smallest and largest values over the square lie
     * at corners. A corner that overflows float gives no beam.
     */
    @Override
    public Beam beam(int left, int top, int right, int bottom, int w, int h) {
        Vector3f[] corners = new Vector3f[4];
        for (int corner = 0; corner < 4; corner++) {
            int x = corner % 2 == 0 ? left : right - 1;
            int y = corner < 2 ? top : bottom - 1;
            corners[corner] = generateRay(x, y, w, h).origin();
        }
        return Beam.around(dir, corners);
    }

    /** The view direction, exactly as the scene file gave it. */
    public Vector3f direction() {
        return dir;
    }

    /** Pixels per world unit. */
    public float zoom() {
        return zoom;
    }

    /** The image's right axis u. */
    public Vector3f widthVector() {
        return widthVector;
    }

    /** The image's down axis v. */
    public Vector3f heightVector() {
        return heightVector;
    }
}
