package rtd.camera;

import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A pinhole camera, the perspective projection that section 3.2.1 describes beside the
 * orthographic one: every ray starts at the camera's position, and the direction varies from
 * pixel to pixel, so that far objects look smaller (Part II, "The perspective camera").
 *
 * <p>The image is a plane at distance {@code f} pixels in front of the eye, spanned by the same
 * axes u and v as Listing 4.1 ({@link ImageAxes}). {@code f = (w/2) / tan(fov/2)}, with the exact
 * half of the width, so that the image's width spans the field of view {@code fov}.
 */
public final class PerspectiveCamera implements ICamera {

    private final Vector3f pos;
    private final Vector3f dir;
    /** The point the scene file told the camera to look at, or null if it gave a direction. */
    private final Vector3f target;
    private final float fieldOfView;
    private final Vector3f forward;
    private final Vector3f widthVector;
    private final Vector3f heightVector;
    /** {@code 1 / tan(fov/2)}, so that {@code f = (w/2) · focal}. */
    private final double focal;

    /**
     * Makes a camera at {@code pos} that looks along {@code dir} (any non-zero length) with a
     * horizontal field of view of {@code fieldOfView} degrees, {@code 0 < fov < 180}.
     */
    public PerspectiveCamera(Vector3f pos, Vector3f dir, float fieldOfView) {
        this(pos, dir, null, fieldOfView);
    }

    /**
     * Makes a camera at {@code pos} that looks at the point {@code target} (not {@code pos}):
     * its direction is {@code target − pos} (Part III, "A camera that looks at a point"), and it
     * has a horizontal field of view of {@code fieldOfView} degrees.
     */
    public static PerspectiveCamera lookingAt(Vector3f pos, Vector3f target, float fieldOfView) {
        return new PerspectiveCamera(pos, target.subtract(pos), target, fieldOfView);
    }

    private PerspectiveCamera(Vector3f pos, Vector3f dir, Vector3f target, float fieldOfView) {
        this.pos = pos;
        this.dir = dir;
        this.target = target;
        this.fieldOfView = fieldOfView;
        this.forward = dir.normalize();
        ImageAxes axes = ImageAxes.of(dir);
        this.widthVector = axes.u();
        this.heightVector = axes.v();
        this.focal = 1 / Math.tan(Math.toRadians(fieldOfView) / 2);
    }

    /** The ray through the pixel's corner: {@link #generateRay(float, float, int, int)} at whole numbers. */
    @Override
    public Ray generateRay(int x, int y, int w, int h) {
        return generateRay((float) x, (float) y, w, h);
    }

    /**
     * Origin {@code pos}, direction {@code normalize(dir)·f + u·x' + v·y'} with
     * {@code x' = x − w/2}, {@code y' = y − h/2} (integer division, as Listing 4.1). Every
     * renderer makes its rays here.
     */
    @Override
    public Ray generateRay(float x, float y, int w, int h) {
        float offsetX = x - (w / 2);
        float offsetY = y - (h / 2);
        float f = focalLength(w);
        Vector3f direction = forward.multiply(f).add(widthVector.multiply(offsetX)).add(heightVector.multiply(offsetY));
        return new Ray(pos, direction);
    }

    /** {@code f}, the image plane's distance from the eye in pixels, for a picture {@code w} pixels wide. */
    public float focalLength(int w) {
        return (float) (w / 2.0 * focal);
    }

    /** The unit view direction, {@code normalize(dir)}. */
    public Vector3f forward() {
        return forward;
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

    /** The horizontal field of view in degrees. */
    public float fieldOfView() {
        return fieldOfView;
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
