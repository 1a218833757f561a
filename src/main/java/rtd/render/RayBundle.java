package rtd.render;

import rtd.camera.ICamera;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The rays of one small square of pixels, kept as numbers: the origin and direction of ray {@code i} of equation 3.1
 * at index {@code i}, row by row. {@link ParallelRenderer} fills one per thread and hands it to a {@link Tracer}, which
 * may use what the rays share (a view grid: the pixels they pass through). The rays are made only when a tracer first
 * asks for their numbers ({@link #make}), so a tracer that can tell from the pixels that no ray reaches any object
 * never needs them; as numbers the camera writes ({@link ICamera#putRay}, exactly {@link ICamera#generateRay}'s), not
 * as a {@link Ray} of 48 bytes on the heap per pixel.
 */
public final class RayBundle {

    private final float[] originX;
    private final float[] originY;
    private final float[] originZ;
    private final float[] directionX;
    private final float[] directionY;
    private final float[] directionZ;
    private int count;
    /** One ray's numbers as the camera writes them ({@link ICamera#putRay}), before they are stored. */
    private final float[] numbers = new float[6];
    /** The pixels whose rays these are, or null if the rays were given one by one. */
    private Pixels pixels;
    private boolean made;

    /**
     * The pixels {@code [left, right) × [top, bottom)} of a {@code width × height} picture whose camera's rays a bundle
     * holds, each ray through the point {@code (x + sampleX, y + sampleY)} of its pixel: (0, 0) is the corner (Listing
     * 4.1), else a sample's offset.
     */
    public record Pixels(ICamera camera, int left, int top, int right, int bottom, int width, int height, float sampleX,
            float sampleY) {

        /**
         * The camera's ray {@code i}, row by row: through its pixel's corner, as Listing 4.1, or the sample's point.
         */
        Ray ray(int i) {
            int x = left + i % (right - left);
            int y = top + i / (right - left);
            if (sampleX == 0 && sampleY == 0) {
                return camera.generateRay(x, y, width, height);
            }
            return camera.generateRay(x + sampleX, y + sampleY, width, height);
        }
    }

    public RayBundle(int capacity) {
        originX = new float[capacity];
        originY = new float[capacity];
        originZ = new float[capacity];
        directionX = new float[capacity];
        directionY = new float[capacity];
        directionZ = new float[capacity];
    }

    /** The camera's rays (Listing 4.1) of pixels {@code [left, right) × [top, bottom)}. */
    public void fill(ICamera camera, int left, int top, int right, int bottom, int width, int height) {
        fill(camera, left, top, right, bottom, width, height, 0, 0);
    }

    /** As above, each ray through the point {@code (x + sampleX, y + sampleY)} of its pixel (anti-aliasing). */
    public void fill(ICamera camera, int left, int top, int right, int bottom, int width, int height, float sampleX,
            float sampleY) {
        pixels = new Pixels(camera, left, top, right, bottom, width, height, sampleX, sampleY);
        count = (right - left) * (bottom - top);
        made = false;
    }

    /** These rays, for tests that choose their own. */
    public void fill(Ray... rays) {
        pixels = null;
        count = 0;
        for (Ray ray : rays) {
            Vector3f o = ray.origin();
            Vector3f d = ray.direction();
            System.arraycopy(new float[] {o.x(), o.y(), o.z(), d.x(), d.y(), d.z()}, 0, numbers, 0, 6);
            store(count++);
        }
        made = true;
    }

    /** Makes the rays with the camera, if not done yet: before reading a ray's numbers. */
    public void make() {
        if (made) {
            return;
        }
        Pixels p = pixels;
        int i = 0;
        for (int y = p.top; y < p.bottom; y++) {
            for (int x = p.left; x < p.right; x++) {
                p.camera.putRay(x + p.sampleX, y + p.sampleY, p.width, p.height, numbers, 0);
                store(i++);
            }
        }
        made = true;
    }

    /** The camera whose pixels these rays are, or {@code null} if they were given one by one. */
    public ICamera camera() {
        return pixels == null ? null : pixels.camera;
    }

    /** The pixels whose rays these are, for a tracer that knows the camera; null if the rays were given one by one. */
    public Pixels pixels() {
        return pixels;
    }

    private void store(int i) {
        originX[i] = numbers[0];
        originY[i] = numbers[1];
        originZ[i] = numbers[2];
        directionX[i] = numbers[3];
        directionY[i] = numbers[4];
        directionZ[i] = numbers[5];
    }

    public int count() {
        return count;
    }

    /** Ray {@code i} for tracers that take one ray at a time: straight from the camera (unmade), or as it was given. */
    public Ray ray(int i) {
        if (pixels != null && !made) {
            return pixels.ray(i);
        }
        return new Ray(new Vector3f(originX[i], originY[i], originZ[i]),
                new Vector3f(directionX[i], directionY[i], directionZ[i]));
    }

    // Ray i's numbers, for tracers that keep a ray as numbers; only after make().

    public float originX(int i) {
        return originX[i];
    }

    public float originY(int i) {
        return originY[i];
    }

    public float originZ(int i) {
        return originZ[i];
    }

    public float directionX(int i) {
        return directionX[i];
    }

    public float directionY(int i) {
        return directionY[i];
    }

    public float directionZ(int i) {
        return directionZ[i];
    }
}
