package rtd.accel;

import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.Tracer;
import rtd.render.WorkCount;
import rtd.scene.Color;

/**
 * Follows rays through a {@link Bvh}: the same answer as the paper's loop over all objects
 * (Listing 4.3), found by visiting only the boxes the ray passes through.
 *
 * <p>Of a node's two children the ray visits the nearer box first; once it has a hit, it skips
 * every box that it enters only beyond that hit. At the leaves it runs the paper's
 * intersection test and depth test unchanged, keeping, as the paper does, the object whose
 * hit is nearest ({@code |P − O|}), and on a tie the one that comes first in the file.
 *
 * <p>Not thread-safe: it keeps a stack and counters of its own. Use one per thread.
 */
public final class BvhTracer implements Tracer {

    /**
     * How much farther than the nearest hit a box may start and still be visited. Distances
     * and box entries round differently; this margin (relative, and relative to the origin's
     * size) keeps a box whose object could tie or win by a rounding error.
     */
    private static final float SKIP_MARGIN = 1e-5f;
    /** The entry of a box the ray misses. */
    private static final float MISS = Float.POSITIVE_INFINITY;

    private final Bvh bvh;
    private final int[] stackNodes;
    private final float[] stackEntries;
    private long rays;
    private long tests;
    private long nodesVisited;

    BvhTracer(Bvh bvh) {
        this.bvh = bvh;
        this.stackNodes = new int[bvh.maxDepth + 2];
        this.stackEntries = new float[bvh.maxDepth + 2];
    }

    @Override
    public Color trace(Ray ray) {
        rays++;
        Vector3f origin = ray.origin();
        int nearest = nearestObject(origin.x(), origin.y(), origin.z(), ray.direction());
        return nearest < 0 ? bvh.ambient : bvh.objects[nearest].color();
    }

    @Override
    public WorkCount work() {
        return new WorkCount(rays, tests, nodesVisited);
    }

    /**
     * The place in {@code bvh.objects} of the object the ray sees, or −1 for none.
     *
     * <p>It takes the ray's origin as three numbers and makes its own {@code Ray}: this method
     * is too long for the JIT to inline, and a {@code Ray} passed in would have to be allocated
     * for every pixel, while one made here stays in registers.
     */
    private int nearestObject(float ox, float oy, float oz, Vector3f direction) {
        // Local copies: the JIT keeps them in registers through the loop.
        float[] bounds = bvh.bounds;
        int[] nodes = bvh.nodes;
        IGeometry[] objects = bvh.objects;
        int[] fileOrder = bvh.fileOrder;
        Vector3f origin = new Vector3f(ox, oy, oz);
        Ray ray = new Ray(origin, direction);
        float ix = 1f / direction.x();
        float iy = 1f / direction.y();
        float iz = 1f / direction.z();
        float margin = SKIP_MARGIN * origin.magnitude() / direction.magnitude();

        int best = -1;
        float bestDistance = Float.POSITIVE_INFINITY;
        float skipBeyond = Float.POSITIVE_INFINITY;
        int visited = 0;
        int tested = 0;
        int stackSize = 0;
        int node = 0;
        if (entry(bounds, node, ox, oy, oz, ix, iy, iz) == MISS) {
            nodesVisited++;
            return -1;
        }
        while (true) {
            visited++;
            int first = nodes[2 * node];
            int count = nodes[2 * node + 1];
            if (count != Bvh.INNER) {
                for (int i = first; i < first + count; i++) {
                    tested++;
                    Intersection intersection = objects[i].intersect(ray);
                    if (intersection.happened()) {
                        float distance = intersection.contactCoord().subtract(origin).magnitude();
                        if (distance < bestDistance
                                || (distance == bestDistance && best >= 0 && fileOrder[i] < fileOrder[best])) {
                            best = i;
                            bestDistance = distance;
                            float t = intersection.t();
                            skipBeyond = t + t * SKIP_MARGIN + margin;
                        }
                    }
                }
            } else {
                int near = first;
                int far = first + 1;
                float nearEntry = entry(bounds, near, ox, oy, oz, ix, iy, iz);
                float farEntry = entry(bounds, far, ox, oy, oz, ix, iy, iz);
                if (farEntry < nearEntry) {
                    int swapNode = near;
                    near = far;
                    far = swapNode;
                    float swapEntry = nearEntry;
                    nearEntry = farEntry;
                    farEntry = swapEntry;
                }
                if (worthVisiting(farEntry, skipBeyond)) {
                    stackNodes[stackSize] = far;
                    stackEntries[stackSize] = farEntry;
                    stackSize++;
                }
                if (worthVisiting(nearEntry, skipBeyond)) {
                    node = near;
                    continue;
                }
            }
            do {
                if (stackSize == 0) {
                    nodesVisited += visited;
                    tests += tested;
                    return best;
                }
                stackSize--;
                node = stackNodes[stackSize];
            } while (stackEntries[stackSize] > skipBeyond);
        }
    }

    /** Whether the ray enters a box ({@code entry} finite) no farther than {@code skipBeyond}. */
    private static boolean worthVisiting(float entry, float skipBeyond) {
        return entry != MISS && entry <= skipBeyond;
    }

    /**
     * The slab test: the ray parameter t at which the ray enters node's box, or infinity if it
     * misses it ({@link #MISS}). Negative when the origin lies inside the box.
     */
    private static float entry(float[] bounds, int node, float ox, float oy, float oz, float ix, float iy, float iz) {
        int at = 6 * node;
        float x0 = (bounds[at] - ox) * ix;
        float x1 = (bounds[at + 3] - ox) * ix;
        float y0 = (bounds[at + 1] - oy) * iy;
        float y1 = (bounds[at + 4] - oy) * iy;
        float z0 = (bounds[at + 2] - oz) * iz;
        float z1 = (bounds[at + 5] - oz) * iz;
        float enter = FastMath.max(FastMath.max(FastMath.min(x0, x1), FastMath.min(y0, y1)), FastMath.min(z0, z1));
        float exit = FastMath.min(FastMath.min(FastMath.max(x0, x1), FastMath.max(y0, y1)), FastMath.max(z0, z1));
        return enter <= exit && exit >= 0 ? enter : MISS;
    }
}
