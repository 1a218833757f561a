package rtd.render;

import rtd.camera.ICamera;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The rays of one small square of pixels, kept as numbers: the origin and direction of ray
 * {@code i} of equation 3.1 at index {@code i}, row by row. Not in the paper:
 * {@link ParallelRenderer} fills one per thread and hands it to a {@link Tracer}, which may use
 * what the rays share (the orthographic camera's are all parallel).
 *
 * <p>Numbers, not {@link Ray} objects: a {@code Ray} stored in an array lives on the heap, 48
 * bytes a pixel; here the camera's {@code Ray} is only read, so once the JIT has inlined
 * {@link ICamera#generateRay} it never exists as an object.
 */
public final class RayBundle {

    private final float[] originX;
    private final float[] originY;
    private final float[] originZ;
    private final float[] directionX;
    private final float[] directionY;
    private final float[] directionZ;
    private int count;

    /** An empty bundle with room for {@code capacity} rays. */
    public RayBundle(int capacity) {
        originX = new float[capacity];
        originY = new float[capacity];
        originZ = new float[capacity];
        directionX = new float[capacity];
        directionY = new float[capacity];
        directionZ = new float[capacity];
    }

    /**
     * Replaces the rays with the camera's rays (Listing 4.1) for the pixels
     * {@code [left, right) × [top, bottom)} of a {@code width × height} image, row by row.
     */
    public void fill(ICamera camera, int left, int top, int right, int bottom, int width, int height) {
        count = 0;
        for (int y = top; y < bottom; y++) {
            for (int x = left; x < right; x++) {
                store(count++, camera.generateRay(x, y, width, height));
            }
        }
    }

    /** Replaces the rays with these (for tests and benchmarks that choose their own rays). */
    public void fill(Ray... rays) {
        count = 0;
        for (Ray ray : rays) {
            store(count++, ray);
        }
    }

    private void store(int i, Ray ray) {
        Vector3f origin = ray.origin();
        Vector3f direction = ray.direction();
        originX[i] = origin.x();
        originY[i] = origin.y();
        originZ[i] = origin.z();
        directionX[i] = direction.x();
        directionY[i] = direction.y();
        directionZ[i] = direction.z();
    }

    /** The number of rays. */
    public int count() {
        return count;
    }

    /** Ray {@code i} as a {@link Ray}, for tracers that take one ray at a time. */
    public Ray ray(int i) {
        return new Ray(new Vector3f(originX[i], originY[i], originZ[i]),
                new Vector3f(directionX[i], directionY[i], directionZ[i]));
    }

    // Ray i's numbers, for tracers that keep a ray as numbers.

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
