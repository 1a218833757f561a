package rtd.accel;

import rtd.camera.Beam;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.render.WorkCount;
import rtd.scene.Color;

/**
 * Follows rays through a {@link Bvh}: the same answer as the paper's loop over all objects
 * (Listing 4.3), found by visiting only the boxes the ray passes through.
 *
 * <p>Of a node's two children the ray visits the nearer box first; once it has a hit, it skips
 * every box that it enters only beyond that hit. At the leaves it runs the paper's
 * intersection test and depth test unchanged ({@link NearestHit}).
 *
 * <p>Rays that share a direction (the orthographic camera's) and come as a bundle, through
 * {@link #traceAll}, walk the tree together ({@link BeamTracer}).
 *
 * <p>Not thread-safe: it keeps a stack and counters of its own. Use one per thread.
 */
public final class BvhTracer implements Tracer {

    private final Bvh bvh;
    private final NearestHit hit;
    private final BeamTracer beam;
    private final int[] stackNodes;
    private final float[] stackEntries;
    private long rays;
    private long nodesVisited;

    BvhTracer(Bvh bvh) {
        this.bvh = bvh;
        this.hit = new NearestHit(bvh);
        this.beam = new BeamTracer(bvh);
        this.stackNodes = new int[bvh.maxDepth + 2];
        this.stackEntries = new float[bvh.maxDepth + 2];
    }

    @Override
    public Color trace(Ray ray) {
        rays++;
        Vector3f origin = ray.origin();
        Vector3f direction = ray.direction();
        hit.start(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
        walkTree();
        return hit.colour();
    }

    /** Parallel rays walk the tree together ({@link BeamTracer}); others walk it one by one. */
    @Override
    public void traceAll(RayBundle bundle, int[] rgb) {
        Beam shared = bundle.beam();
        if (shared == null || !beam.trace(bundle, shared, rgb)) {
            Tracer.super.traceAll(bundle, rgb);
        }
    }

    @Override
    public WorkCount work() {
        WorkCount beams = beam.work();
        return new WorkCount(rays + beams.rays(), hit.tests() + beams.intersectionTests(),
                nodesVisited + beams.nodesVisited());
    }

    /** Walks down the tree, nearer child first, skipping boxes entered beyond the nearest hit. */
    private void walkTree() {
        int[] nodes = bvh.nodes;
        int stackSize = 0;
        int node = 0;
        if (hit.entry(node) == NearestHit.MISS) {
            nodesVisited++;
            return;
        }
        while (true) {
            nodesVisited++;
            int first = nodes[2 * node];
            if (nodes[2 * node + 1] != Bvh.INNER) {
                hit.testLeaf(node);
            } else {
                int near = first;
                int far = first + 1;
                float nearEntry = hit.entry(near);
                float farEntry = hit.entry(far);
                if (farEntry < nearEntry) {
                    int swapNode = near;
                    near = far;
                    far = swapNode;
                    float swapEntry = nearEntry;
                    nearEntry = farEntry;
                    farEntry = swapEntry;
                }
                if (hit.worthVisiting(farEntry)) {
                    stackNodes[stackSize] = far;
                    stackEntries[stackSize] = farEntry;
                    stackSize++;
                }
                if (hit.worthVisiting(nearEntry)) {
                    node = near;
                    continue;
                }
            }
            do {
                if (stackSize == 0) {
                    return;
                }
                stackSize--;
                node = stackNodes[stackSize];
            } while (stackEntries[stackSize] > hit.skipBeyond());
        }
    }
}
