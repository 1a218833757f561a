package rtd.accel;

import java.util.Arrays;
import rtd.camera.Beam;
import rtd.geometry.Intersection;
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
 * intersection test and depth test unchanged, keeping, as the paper does, the object whose
 * hit is nearest ({@code |P − O|}), and on a tie the one that comes first in the file.
 *
 * <p>Rays that share a direction (the orthographic camera's) and come as a bundle, through
 * {@link #traceAll}, skip the walk down the tree: {@link BeamLeaves} walks it once for the
 * whole bundle, and each ray tests just those leaves, nearest first, with the same skipping.
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
    private final BeamLeaves beam;
    private final int[] stackNodes;
    private final float[] stackEntries;
    private long rays;
    private long tests;
    private long nodesVisited;

    // The ray being traced, as numbers (a Ray kept in a field would be allocated for every
    // ray), and the nearest hit so far.
    private float ox;
    private float oy;
    private float oz;
    private float dx;
    private float dy;
    private float dz;
    private float dd;
    private float ix;
    private float iy;
    private float iz;
    private float margin;
    private int best;
    private float bestDistance;
    private float skipBeyond;

    BvhTracer(Bvh bvh) {
        this.bvh = bvh;
        this.beam = new BeamLeaves(bvh);
        this.stackNodes = new int[bvh.maxDepth + 2];
        this.stackEntries = new float[bvh.maxDepth + 2];
    }

    @Override
    public Color trace(Ray ray) {
        start(ray);
        walkTree();
        return colour();
    }

    /**
     * Parallel rays share one walk down the tree ({@link BeamLeaves}); others walk it one by
     * one. If the walk finds no leaf, every ray sees the background, and none is even made.
     */
    @Override
    public void traceAll(RayBundle rays, int[] rgb) {
        Beam shared = rays.beam();
        if (shared == null || !beam.collect(shared)) {
            Tracer.super.traceAll(rays, rgb);
            return;
        }
        if (beam.count() == 0) {
            this.rays += rays.count();
            Arrays.fill(rgb, 0, rays.count(), bvh.ambient.getRGB());
            return;
        }
        rays.make();
        for (int i = 0; i < rays.count(); i++) {
            start(rays.originX(i), rays.originY(i), rays.originZ(i),
                    rays.directionX(i), rays.directionY(i), rays.directionZ(i));
            testBeamLeaves();
            rgb[i] = colour().getRGB();
        }
    }

    @Override
    public WorkCount work() {
        return new WorkCount(rays, tests, nodesVisited + beam.nodesVisited());
    }

    private void start(Ray next) {
        Vector3f origin = next.origin();
        Vector3f direction = next.direction();
        start(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
    }

    private void start(float originX, float originY, float originZ,
            float directionX, float directionY, float directionZ) {
        rays++;
        ox = originX;
        oy = originY;
        oz = originZ;
        dx = directionX;
        dy = directionY;
        dz = directionZ;
        dd = (dx * dx) + (dy * dy) + (dz * dz); // D·D, summed as Vector3f.dot sums
        ix = 1f / dx;
        iy = 1f / dy;
        iz = 1f / dz;
        margin = SKIP_MARGIN * (float) Math.sqrt(ox * ox + oy * oy + oz * oz) / (float) Math.sqrt(dd);
        best = -1;
        bestDistance = Float.POSITIVE_INFINITY;
        skipBeyond = Float.POSITIVE_INFINITY;
    }

    private Color colour() {
        return best < 0 ? bvh.ambient : bvh.objects[best].color();
    }

    /** Walks down the tree, nearer child first, skipping boxes entered beyond the nearest hit. */
    private void walkTree() {
        int[] nodes = bvh.nodes;
        int stackSize = 0;
        int node = 0;
        if (entry(node) == MISS) {
            nodesVisited++;
            return;
        }
        while (true) {
            nodesVisited++;
            int first = nodes[2 * node];
            if (nodes[2 * node + 1] != Bvh.INNER) {
                testLeaf(node);
            } else {
                int near = first;
                int far = first + 1;
                float nearEntry = entry(near);
                float farEntry = entry(far);
                if (farEntry < nearEntry) {
                    int swapNode = near;
                    near = far;
                    far = swapNode;
                    float swapEntry = nearEntry;
                    nearEntry = farEntry;
                    farEntry = swapEntry;
                }
                if (worthVisiting(farEntry)) {
                    stackNodes[stackSize] = far;
                    stackEntries[stackSize] = farEntry;
                    stackSize++;
                }
                if (worthVisiting(nearEntry)) {
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
            } while (stackEntries[stackSize] > skipBeyond);
        }
    }

    /** Tests the leaves the beam found, nearest first, until the rest start beyond the nearest hit. */
    private void testBeamLeaves() {
        for (int i = 0; i < beam.count() && beam.entry(i) <= skipBeyond; i++) {
            int leaf = beam.leaf(i);
            nodesVisited++;
            if (worthVisiting(entry(leaf))) {
                testLeaf(leaf);
            }
        }
    }

    /** Whether the ray enters a box ({@code entry} finite) no farther than the nearest hit allows. */
    private boolean worthVisiting(float entry) {
        return entry != MISS && entry <= skipBeyond;
    }

    /**
     * The paper's intersection test and depth test on a leaf's objects: the nearest hit
     * ({@code |P − O|}) wins, and on a tie the object that comes first in the file.
     */
    private void testLeaf(int leaf) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        PackedSpheres spheres = bvh.spheres;
        int[] fileOrder = bvh.fileOrder;
        for (int i = first; i < end; i++) {
            tests++;
            float t;
            float distance;
            if (spheres != null) {
                t = spheres.hit(i, ox, oy, oz, dx, dy, dz, dd);
                distance = PackedSpheres.distance(t, ox, oy, oz, dx, dy, dz);
            } else {
                Vector3f origin = new Vector3f(ox, oy, oz);
                Intersection intersection = bvh.objects[i].intersect(new Ray(origin, new Vector3f(dx, dy, dz)));
                t = intersection.t();
                distance = intersection.contactCoord().subtract(origin).magnitude();
            }
            if (t >= 0 // false for NaN: no hit
                    && (distance < bestDistance
                            || distance == bestDistance && best >= 0 && fileOrder[i] < fileOrder[best])) {
                best = i;
                bestDistance = distance;
                skipBeyond = t + t * SKIP_MARGIN + margin;
            }
        }
    }

    /**
     * The slab test: the ray parameter t at which the ray enters node's box, or infinity if it
     * misses it ({@link #MISS}). Negative when the origin lies inside the box.
     */
    private float entry(int node) {
        float[] bounds = bvh.bounds;
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
