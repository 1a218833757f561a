package rtd.camera;

import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The paper's camera: an orthographic (parallel) projection (section 3.2.1, Listing 4.1).
 *
 * <p>All rays share the view direction; their origins lie on a plane through the camera's
 * position, spread out along two image axes: {@code widthVector} (u) points right in the
 * image and {@code heightVector} (v) points down ({@link ImageAxes}). {@code zoom} is how many
 * pixels one world unit covers.
 */
public final class OrthographicCamera implements ICamera {

    private final Vector3f pos;
    private final Vector3f dir;
    /** The point the scene file told the camera to look at, or null if it gave a direction. */
    private final Vector3f target;
    private final float zoom;
    private final Vector3f widthVector;
    private final Vector3f heightVector;

    /**
     * Makes a camera at {@code pos} that looks along {@code dir} (any non-zero length) and
     * shows {@code zoom} pixels per world unit.
     */
    public OrthographicCamera(Vector3f pos, Vector3f dir, float zoom) {
        this(pos, dir, null, zoom);
    }

    /**
     * Makes a camera at {@code pos} that looks at the point {@code target} (not {@code pos}):
     * its direction is {@code target − pos} (Part III, "A camera that looks at a point"), and it
     * shows {@code zoom} pixels per world unit.
     */
    public static OrthographicCamera lookingAt(Vector3f pos, Vector3f target, float zoom) {
        return new OrthographicCamera(pos, target.subtract(pos), target, zoom);
    }

    private OrthographicCamera(Vector3f pos, Vector3f dir, Vector3f target, float zoom) {
        this.pos = pos;
        this.dir = dir;
        this.target = target;
        this.zoom = zoom;
        ImageAxes axes = ImageAxes.of(dir);
        this.widthVector = axes.u();
        this.heightVector = axes.v();
    }

    /** The ray from the pixel's corner: {@link #generateRay(float, float, int, int)} at whole numbers. */
    @Override
    public Ray generateRay(int x, int y, int w, int h) {
        return generateRay((float) x, (float) y, w, h);
    }

    /**
     * Listing 4.1: the point's offset from the image centre ({@code w / 2} is the integer
     * division, so that a whole number gives a ray from the pixel's corner) moves the origin
     * along u and v; the direction stays {@code dir}. The operations run in the paper's order,
     * for the same rounding. Every renderer makes its rays here.
     */
    @Override
    public Ray generateRay(float x, float y, int w, int h) {
        float offsetX = x - (w / 2);
        float offsetY = y - (h / 2);
        Vector3f origin = new Vector3f(originAlong(pos.x(), widthVector.x(), heightVector.x(), offsetX, offsetY),
                originAlong(pos.y(), widthVector.y(), heightVector.y(), offsetX, offsetY),
                originAlong(pos.z(), widthVector.z(), heightVector.z(), offsetX, offsetY));
        return new Ray(origin, dir);
    }

    /** {@link #generateRay(float, float, int, int)}'s numbers, written without making a ray. */
    @Override
    public void putRay(float x, float y, int w, int h, float[] into, int at) {
        float offsetX = x - (w / 2);
        float offsetY = y - (h / 2);
        into[at] = originAlong(pos.x(), widthVector.x(), heightVector.x(), offsetX, offsetY);
        into[at + 1] = originAlong(pos.y(), widthVector.y(), heightVector.y(), offsetX, offsetY);
        into[at + 2] = originAlong(pos.z(), widthVector.z(), heightVector.z(), offsetX, offsetY);
        into[at + 3] = dir.x();
        into[at + 4] = dir.y();
        into[at + 5] = dir.z();
    }

    /**
     * Listing 4.1 for one coordinate of the origin: {@code pos + (u · offsetX / zoom + v · offsetY / zoom)},
     * in the paper's order of operations, so each coordinate rounds as the paper's vector arithmetic does.
     */
    private float originAlong(float position, float u, float v, float offsetX, float offsetY) {
        return position + (u * offsetX / zoom + v * offsetY / zoom);
    }

    @Override
    public Vector3f position() {
        return pos;
    }

    /** The view direction, exactly as the scene file gave it, or {@code target − pos}. */
    public Vector3f direction() {
        return dir;
    }

    /** The point the scene file told the camera to look at, or null if it gave a direction. */
    public Vector3f target() {
        return target;
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
