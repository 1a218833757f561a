package rtd.window;

import java.math.BigDecimal;
import java.util.List;
import java.util.function.BinaryOperator;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.BoundingBox;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;

/**
 * The window's camera as the mouse moves it from the file's camera: orbit around what the centre pixel sees
 * ({@link #pivot}), pan across the view, zoom ({@code R} starts a new controller on the file's camera); and the camera
 * written back as a scene line ({@link #line}). Both of rtd's cameras: the orthographic camera zooms by its zoom
 * (pixels per world unit), the perspective camera moves along its view. The position and direction are kept in
 * double, so that many small moves add no float error; each camera made from them is the file's kind, in float.
 *
 * <p>An orbit turns the position about the point, and the direction with it, first about the world's vertical (yaw),
 * then about the view's horizontal right axis (pitch); the view stays at least {@value #STEEPEST_DEGREES}° from
 * straight up or down, where its right axis would turn over.
 */
final class CameraController {

    static final double STEEPEST_DEGREES = 89;
    /** How much one wheel click zooms: the view's scale changes by this factor. */
    static final double ZOOM_STEP = 1.1;
    private static final Vec3 UP = new Vec3(0, 1, 0);

    private final ICamera original;
    private Vec3 position;
    private Vec3 direction;
    private double zoom;
    private boolean moved;

    /** A controller on {@code original}, one of rtd's two cameras: a scene file makes no other. */
    CameraController(ICamera original) {
        this.original = original;
        position = Vec3.of(original.position());
        direction = Vec3.of(original instanceof PerspectiveCamera p ? p.direction() : ((OrthographicCamera) original)
                .direction()).unit();
        zoom = original instanceof OrthographicCamera o ? o.zoom() : 1;
    }

    /** The camera now: the file's own until it is moved. */
    ICamera camera() {
        if (!moved) {
            return original;
        }
        Vector3f pos = position.toFloat();
        Vector3f dir = direction.toFloat();
        return original instanceof PerspectiveCamera perspective ? new PerspectiveCamera(pos, dir,
                perspective.fieldOfView()) : new OrthographicCamera(pos, dir, (float) zoom);
    }

    boolean moved() {
        return moved;
    }

    /**
     * Turns the camera about {@code pivot} by {@code yaw} radians about the world's vertical and {@code pitch} radians
     * about the view's right axis (positive: looking down more), the pitch held within {@value #STEEPEST_DEGREES}° of
     * the horizon.
     */
    void orbit(double yaw, double pitch, Vector3f pivot) {
        Vec3 centre = Vec3.of(pivot);
        Vec3 offset = position.minus(centre).rotated(UP, yaw);
        direction = direction.rotated(UP, yaw);
        double elevation = Math.asin(Math.max(-1, Math.min(1, direction.y())));
        double limit = Math.toRadians(STEEPEST_DEGREES);
        double turned = Math.max(-limit, Math.min(limit, elevation - pitch)) - elevation;
        Vec3 right = rightAxis();
        offset = offset.rotated(right, turned);
        direction = direction.rotated(right, turned).unit();
        position = centre.plus(offset);
        moved = true;
    }

    /**
     * Moves the camera across its view so that the picture follows the mouse by {@code dx, dy} pixels of a picture
     * {@code width} pixels wide, at the depth of {@code pivot} (the perspective camera's pixels grow with depth).
     */
    void pan(double dx, double dy, Vector3f pivot, int width) {
        double perPixel = original instanceof PerspectiveCamera p ? depth(pivot) / p.focalLength(width) : 1 / zoom;
        Vec3 right = rightAxis();
        Vec3 down = direction.cross(right).unit();
        position = position.minus(right.times(dx * perPixel)).minus(down.times(dy * perPixel));
        moved = true;
    }

    /**
     * Zooms in by {@code clicks} wheel clicks (out if negative): the orthographic camera's zoom grows by
     * {@value #ZOOM_STEP} a click; the perspective camera moves along its view, each click a share of the way to
     * {@code pivot}'s depth, so that it comes nearer and never passes it.
     */
    void zoom(double clicks, Vector3f pivot) {
        double factor = Math.pow(ZOOM_STEP, clicks);
        if (original instanceof OrthographicCamera) {
            zoom *= factor;
        } else {
            position = position.plus(direction.times(depth(pivot) * (1 - 1 / factor)));
        }
        moved = true;
    }

    /** How far ahead {@code pivot} lies along the view; 1 if it lies behind. */
    private double depth(Vector3f pivot) {
        double depth = Vec3.of(pivot).minus(position).dot(direction);
        return depth > 0 && Double.isFinite(depth) ? depth : 1;
    }

    /** The view's right axis, as the cameras make it ({@code rtd.camera.ImageAxes}), in double. */
    private Vec3 rightAxis() {
        Vec3 right = direction.cross(UP);
        return right.length() > 1e-12 ? right.unit() : new Vec3(1, 0, 0);
    }

    /**
     * The point the camera orbits around and pans at: what the centre pixel of the {@code width × height} picture sees
     * (its nearest hit, by the paper's depth test), or where it sees nothing, the centre of the box around the objects
     * that have one; with none, a point ahead on the centre ray.
     */
    static Vector3f pivot(Scene scene, int width, int height) {
        Ray centre = scene.camera().generateRay(width / 2, height / 2, width, height);
        Hit hit = scene.nearestHit(centre);
        if (hit != null) {
            return hit.point();
        }
        List<BoundingBox> boxes = scene.objects().stream().map(IGeometry::bounds).filter(BoundingBox::isBounded)
                .toList();
        if (boxes.isEmpty()) {
            return centre.pointAt(10);
        }
        Vector3f min = boxes.stream().map(BoundingBox::min).reduce((a, b) -> each(a, b, Math::min)).orElseThrow();
        Vector3f max = boxes.stream().map(BoundingBox::max).reduce((a, b) -> each(a, b, Math::max)).orElseThrow();
        return new BoundingBox(min, max).centre();
    }

    private static Vector3f each(Vector3f a, Vector3f b, BinaryOperator<Float> pick) {
        return new Vector3f(pick.apply(a.x(), b.x()), pick.apply(a.y(), b.y()), pick.apply(a.z(), b.z()));
    }

    /**
     * The camera as a line of a scene file, {@code perspective_camera:(pos):(dir):(fov)} or
     * {@code orthographic_camera:(pos):(dir):(zoom)}, ready to paste in place of the file's camera: each number is the
     * plain decimal that reads back as the very same float, so the scene with this line renders the window's picture
     * at the window's size, pixel for pixel.
     */
    static String line(ICamera camera) {
        if (camera instanceof PerspectiveCamera p) {
            return "perspective_camera:" + vector(p.position()) + ":" + vector(p.direction()) + ":("
                    + number(p.fieldOfView()) + ")";
        }
        OrthographicCamera o = (OrthographicCamera) camera;
        return "orthographic_camera:" + vector(o.position()) + ":" + vector(o.direction()) + ":(" + number(o.zoom())
                + ")";
    }

    private static String vector(Vector3f v) {
        return "(" + number(v.x()) + "|" + number(v.y()) + "|" + number(v.z()) + ")";
    }

    /** The shortest decimal that reads back as {@code value} (Java's own), without an exponent. */
    static String number(float value) {
        return new BigDecimal(Float.toString(value)).stripTrailingZeros().toPlainString();
    }

    /** A point or direction in double, for the controller's sums. */
    private record Vec3(double x, double y, double z) {

        static Vec3 of(Vector3f v) {
            return new Vec3(v.x(), v.y(), v.z());
        }

        Vector3f toFloat() {
            return new Vector3f((float) x, (float) y, (float) z);
        }

        Vec3 plus(Vec3 o) {
            return new Vec3(x + o.x, y + o.y, z + o.z);
        }

        Vec3 minus(Vec3 o) {
            return new Vec3(x - o.x, y - o.y, z - o.z);
        }

        Vec3 times(double f) {
            return new Vec3(x * f, y * f, z * f);
        }

        double dot(Vec3 o) {
            return x * o.x + y * o.y + z * o.z;
        }

        Vec3 cross(Vec3 o) {
            return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
        }

        double length() {
            return Math.sqrt(dot(this));
        }

        Vec3 unit() {
            return times(1 / length());
        }

        /** Rodrigues' rotation about the unit {@code axis} by {@code angle} radians. */
        Vec3 rotated(Vec3 axis, double angle) {
            double cos = Math.cos(angle);
            double sin = Math.sin(angle);
            return times(cos).plus(axis.cross(this).times(sin)).plus(axis.times(axis.dot(this) * (1 - cos)));
        }
    }
}
