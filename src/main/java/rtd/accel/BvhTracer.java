package rtd.accel;

import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.render.WorkCount;

/**
 * Follows rays through a {@link Bvh}: the same hit as the paper's loop over all objects
 * (Listing 4.3), for any ray, found by visiting only the boxes the ray passes through.
 *
 * <p>Of a node's two children the ray visits the nearer box first; once it has a hit, it skips
 * every box that it enters only beyond that hit. At the leaves it runs the paper's
 * intersection test and depth test unchanged ({@link NearestHit}).
 *
 * <p>This is the hierarchy's one door: {@link #nearestHit} for one ray, {@link #traceAll} for
 * the rays of a square of pixels, {@link #blocked} for a shadow ray.
 *
 * <p>Not thread-safe: it keeps a stack and counters of its own. Use one per thread.
 */
public final class BvhTracer implements Tracer {

    private final Bvh bvh;
    private final NearestHit hit;
    private final RecentBlockers recentBlockers = new RecentBlockers();
    private final int[] stackNodes;
    private final float[] stackEntries;
    private final float[] stackExits;
    private long rays;
    private long nodesVisited;
    /** Whether the walk may stop at the first hit it finds (a shadow ray's question). */
    private boolean anyHitWillDo;

    BvhTracer(Bvh bvh) {
        this.bvh = bvh;
        this.hit = new NearestHit(bvh);
        this.stackNodes = new int[bvh.maxDepth + 2];
        this.stackEntries = new float[bvh.maxDepth + 2];
        this.stackExits = new float[bvh.maxDepth + 2];
    }

    @Override
    public Hit nearestHit(Ray ray) {
        rays++;
        hit.start(ray);
        hit.testUnbounded();
        walkTree();
        return hit.hit(ray);
    }

    /**
     * Whether the ray hits anything nearer than {@code distance}: the objects that blocked the
     * last shadow rays are tried first ({@link RecentBlockers}); then the walk starts as if it had
     * a hit at that distance, so that it skips every box beyond, and stops at the first hit it finds.
     */
    @Override
    public boolean blocked(Ray ray, float distance) {
        rays++;
        hit.start(ray);
        hit.limitTo(distance);
        hit.testUnbounded();
        if (hit.best() < 0) {
            hit.testPlaces(recentBlockers.places());
        }
        if (hit.best() < 0) {
            anyHitWillDo = true;
            walkTree();
            anyHitWillDo = false;
            if (hit.bestPlace() >= 0) {
                recentBlockers.remember(hit.bestPlace());
            }
        }
        return hit.best() >= 0;
    }

    /** The bundle's rays walk the tree one by one, from their numbers, without a {@link Ray} each. */
    @Override
    public void traceAll(RayBundle bundle, HitBuffer hits) {
        bundle.make();
        for (int i = 0; i < bundle.count(); i++) {
            rays++;
            long before = hit.testsRun();
            hit.start(bundle.originX(i), bundle.originY(i), bundle.originZ(i),
                    bundle.directionX(i), bundle.directionY(i), bundle.directionZ(i));
            hit.testUnbounded();
            walkTree();
            hits.set(i, hit.best(), hit.bestT(), hit.bestDistance());
            hits.setTests(i, hit.testsRun() - before);
        }
    }

    @Override
    public WorkCount work() {
        return new WorkCount(rays, hit.testsByKind(), nodesVisited).answeredBy("BVH");
    }

    /**
     * Walks down the tree, nearer child first, skipping boxes entered beyond the nearest hit.
     * Each node on the way knows a t beyond which the ray is not in it (its exit), and its
     * children's boxes grow by the rounding margin for that t.
     */
    private void walkTree() {
        if (!bvh.hasTree()) {
            return;
        }
        int[] nodes = bvh.nodes;
        float reach = hit.reach();
        int stackSize = 0;
        int node = 0;
        nodesVisited++;
        if (!hit.worthVisiting(hit.entry(node, hit.growth(node, reach)))) {
            return;
        }
        float exit = FastMath.min(hit.exit(), reach);
        while (true) {
            int first = nodes[2 * node];
            if (nodes[2 * node + 1] != Bvh.INNER) {
                hit.testLeaf(node);
                if (anyHitWillDo && hit.best() >= 0) {
                    return;
                }
            } else {
                nodesVisited += 2;
                float grow = hit.growth(node, exit); // the node's rounding is its children's largest
                int near = first;
                int far = first + 1;
                float nearEntry = hit.entry(near, grow);
                float nearExit = FastMath.min(hit.exit(), exit);
                float farEntry = hit.entry(far, grow);
                float farExit = FastMath.min(hit.exit(), exit);
                if (farEntry < nearEntry) {
                    int swapNode = near;
                    near = far;
                    far = swapNode;
                    float swap = nearEntry;
                    nearEntry = farEntry;
                    farEntry = swap;
                    swap = nearExit;
                    nearExit = farExit;
                    farExit = swap;
                }
                if (hit.worthVisiting(farEntry)) {
                    stackNodes[stackSize] = far;
                    stackEntries[stackSize] = farEntry;
                    stackExits[stackSize] = farExit;
                    stackSize++;
                }
                if (hit.worthVisiting(nearEntry)) {
                    node = near;
                    exit = nearExit;
                    continue;
                }
            }
            do {
                if (stackSize == 0) {
                    return;
                }
                stackSize--;
                node = stackNodes[stackSize];
                exit = stackExits[stackSize];
            } while (stackEntries[stackSize] > hit.skipBeyond());
        }
    }
}
