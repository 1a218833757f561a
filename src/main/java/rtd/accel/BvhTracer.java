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
        int nearest = nearestObject(ray);
        return nearest < 0 ? bvh.ambient : bvh.objects[nearest].color();
    }

    @Override
    public WorkCount work() {
        return new WorkCount(rays, tests, nodesVisited);
    }

    /** The place in {@code bvh.objects} of the object the ray sees, or −1 for none. */
    private int nearestObject(Ray ray) {
        Vector3f origin = ray.origin();
        Vector3f direction = ray.direction();
        float ox = origin.x();
        float oy = origin.y();
        float oz = origin.z();
        float ix = 1f / direction.x();
        float iy = 1f / direction.y();
        float iz = 1f / direction.z();
        float margin = SKIP_MARGIN * origin.magnitude() / direction.magnitude();

        int best = -1;
        float bestDistance = Float.POSITIVE_INFINITY;
        float skipBeyond = Float.POSITIVE_INFINITY;
        int stackSize = 0;
        int node = 0;
        float entry = entry(node, ox, oy, oz, ix, iy, iz);
        if (entry == Float.POSITIVE_INFINITY) {
            return -1;
        }
        while (true) {
            nodesVisited++;
            int first = bvh.nodes[2 * node];
            int count = bvh.nodes[2 * node + 1];
            if (count > 0) {
                for (int i = first; i < first + count; i++) {
                    tests++;
                    Intersection intersection = bvh.objects[i].intersect(ray);
                    if (intersection.happened()) {
                        float distance = intersection.contactCoord().subtract(origin).magnitude();
                        if (distance < bestDistance
                                || (distance == bestDistance && best >= 0 && bvh.fileOrder[i] < bvh.fileOrder[best])) {
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
                float nearEntry = entry(near, ox, oy, oz, ix, iy, iz);
                float farEntry = entry(far, ox, oy, oz, ix, iy, iz);
                if (farEntry < nearEntry) {
                    int swapNode = near;
                    near = far;
                    far = swapNode;
                    float swapEntry = nearEntry;
                    nearEntry = farEntry;
                    farEntry = swapEntry;
                }
                if (farEntry <= skipBeyond) {
                    stackNodes[stackSize] = far;
                    stackEntries[stackSize] = farEntry;
                    stackSize++;
                }
                if (nearEntry <= skipBeyond) {
                    node = near;
                    continue;
                }
            }
            do {
                if (stackSize == 0) {
                    return best;
                }
                stackSize--;
                node = stackNodes[stackSize];
            } while (stackEntries[stackSize] > skipBeyond);
        }
    }

    /**
     * The slab test: the ray parameter t at which the ray enters node's box, or infinity if it
     * misses it. Negative when the origin lies inside the box.
     */
    private float entry(int node, float ox, float oy, float oz, float ix, float iy, float iz) {
        float[] b = bvh.bounds;
        int at = 6 * node;
        float x0 = (b[at] - ox) * ix;
        float x1 = (b[at + 3] - ox) * ix;
        float y0 = (b[at + 1] - oy) * iy;
        float y1 = (b[at + 4] - oy) * iy;
        float z0 = (b[at + 2] - oz) * iz;
        float z1 = (b[at + 5] - oz) * iz;
        float enter = Math.max(Math.max(Math.min(x0, x1), Math.min(y0, y1)), Math.min(z0, z1));
        float exit = Math.min(Math.min(Math.max(x0, x1), Math.max(y0, y1)), Math.max(z0, z1));
        return enter <= exit && exit >= 0 ? enter : Float.POSITIVE_INFINITY;
    }
}
