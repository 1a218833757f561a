package rtd.accel;

import java.util.Arrays;
import rtd.camera.Beam;
import rtd.render.RayBundle;
import rtd.render.WorkCount;

/**
 * Traces the parallel rays of a square of pixels together through a {@link Bvh}. Not in the
 * paper: it serves the orthographic camera, whose rays all share one direction.
 *
 * <p>Parallel rays from origins within O ± h form a beam: a ray from such an origin passes
 * through a box only if the beam's middle ray passes through the box grown by h. So one walk
 * down the tree with the middle ray and grown boxes visits every box that any ray of the square
 * enters, and the middle ray's entry into a grown box is a t before which no ray of the square
 * enters that box. The boxes grow a little more (a millionth of the numbers involved) than h,
 * so that rounding can never make the beam miss a box that one of its rays enters.
 *
 * <p>The walk is {@link BvhTracer}'s walk for one ray, with the beam's grown boxes in place
 * of the ray's boxes, and the farthest of the rays' nearest hits in place of the ray's own: it
 * goes nearer child first and skips every box the beam enters beyond that, where no ray can
 * find a nearer hit. At a leaf, each ray that enters the leaf's box no farther than its own
 * nearest hit runs the paper's tests on the leaf's objects ({@link NearestHit}). The rays are
 * made only when the walk reaches a leaf where the beam reaches the box of an object: a square
 * that reaches no object is painted with the background without making a single ray.
 */
final class BeamTracer {

    private static final float ROUNDING = 1e-6f;
    private static final float MISS = NearestHit.MISS;

    private final Bvh bvh;
    private final int[] stackNodes;
    private final float[] stackEntries;
    // The beam: the centre and half size of the box around the rays' origins, and 1 / direction.
    private final float[] centre = new float[3];
    private final float[] half = new float[3];
    private final float[] inverse = new float[3];
    /** The rays of the square and their nearest hits; reused from square to square. */
    private NearestHit[] hits = new NearestHit[0];
    private int count;
    private boolean made;
    /** The farthest of the rays' {@link NearestHit#skipBeyond}: no box beyond it can matter. */
    private float farthestSkip;
    private long rays;
    private long nodesVisited;

    BeamTracer(Bvh bvh) {
        this.bvh = bvh;
        this.stackNodes = new int[bvh.maxDepth + 2];
        this.stackEntries = new float[bvh.maxDepth + 2];
    }

    /**
     * Traces the bundle's rays, all parallel and within {@code beam}, into {@code rgb}
     * ({@code 0xRRGGBB}); false, having traced nothing, if the origins are too far out for
     * float to hold the beam's size.
     */
    boolean trace(RayBundle bundle, Beam beam, int[] rgb) {
        if (!aim(beam)) {
            return false;
        }
        count = bundle.count();
        if (hits.length < count) { // the old ones keep their counts of tests
            int old = hits.length;
            hits = Arrays.copyOf(hits, count);
            for (int i = old; i < count; i++) {
                hits[i] = new NearestHit(bvh);
            }
        }
        made = false;
        farthestSkip = Float.POSITIVE_INFINITY;
        walk(bundle);
        rays += count;
        if (!made) { // no ray reached an object
            Arrays.fill(rgb, 0, count, bvh.ambient.getRGB());
            return true;
        }
        for (int i = 0; i < count; i++) {
            rgb[i] = hits[i].rgb();
        }
        return true;
    }

    /** The work done so far: rays, intersection tests, and nodes visited by walks and by rays at leaves. */
    WorkCount work() {
        long tests = 0;
        for (NearestHit hit : hits) {
            tests += hit.tests();
        }
        return new WorkCount(rays, tests, nodesVisited);
    }

    private boolean aim(Beam beam) {
        float[] lowest = {beam.lowestOrigin().x(), beam.lowestOrigin().y(), beam.lowestOrigin().z()};
        float[] highest = {beam.highestOrigin().x(), beam.highestOrigin().y(), beam.highestOrigin().z()};
        for (int k = 0; k < 3; k++) {
            centre[k] = (lowest[k] + highest[k]) / 2;
            half[k] = (highest[k] - lowest[k]) / 2 + ROUNDING * (Math.abs(lowest[k]) + Math.abs(highest[k]));
            if (!Float.isFinite(centre[k]) || !Float.isFinite(half[k])) {
                return false;
            }
        }
        inverse[0] = 1f / beam.direction().x();
        inverse[1] = 1f / beam.direction().y();
        inverse[2] = 1f / beam.direction().z();
        return true;
    }

    /** Walks down the tree, nearer child first, skipping boxes entered beyond every ray's nearest hit. */
    private void walk(RayBundle bundle) {
        int[] nodes = bvh.nodes;
        int stackSize = 0;
        int node = 0;
        nodesVisited++;
        if (grownEntry(bvh.bounds, node) == MISS) {
            return;
        }
        while (true) {
            int first = nodes[2 * node];
            if (nodes[2 * node + 1] != Bvh.INNER) {
                testLeaf(bundle, node);
            } else {
                nodesVisited += 2;
                int near = first;
                int far = first + 1;
                float nearEntry = grownEntry(bvh.bounds, near);
                float farEntry = grownEntry(bvh.bounds, far);
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
            } while (stackEntries[stackSize] > farthestSkip);
        }
    }

    private boolean worthVisiting(float entry) {
        return entry != MISS && entry <= farthestSkip;
    }

    /**
     * Runs the paper's tests on the leaf's objects for each ray that could find a nearer hit
     * there. {@code reach}, the beam's entry into the nearest of the objects' boxes, is a t
     * before which no ray of the square hits any of them.
     */
    private void testLeaf(RayBundle bundle, int leaf) {
        float reach = objectsEntry(leaf);
        if (!worthVisiting(reach)) {
            return;
        }
        if (!made) {
            bundle.make();
            for (int i = 0; i < count; i++) {
                hits[i].start(bundle.originX(i), bundle.originY(i), bundle.originZ(i),
                        bundle.directionX(i), bundle.directionY(i), bundle.directionZ(i));
            }
            made = true;
        }
        float farthest = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            NearestHit hit = hits[i];
            if (reach <= hit.skipBeyond()) {
                nodesVisited++;
                if (hit.worthVisiting(hit.entry(leaf))) {
                    hit.testLeaf(leaf);
                }
            }
            farthest = FastMath.max(farthest, hit.skipBeyond());
        }
        farthestSkip = farthest;
    }

    /** The beam's entry into the nearest box of the leaf's objects, or {@link #MISS} if it reaches none. */
    private float objectsEntry(int leaf) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        float entry = MISS;
        for (int i = first; i < end; i++) {
            entry = FastMath.min(entry, grownEntry(bvh.objectBounds, i));
        }
        return entry;
    }

    /** The slab test of the middle ray against box {@code i} of {@code boxes}, grown by {@code half}. */
    private float grownEntry(float[] boxes, int i) {
        float enter = Float.NEGATIVE_INFINITY;
        float exit = Float.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            float min = boxes[6 * i + k];
            float max = boxes[6 * i + 3 + k];
            float grow = half[k] + ROUNDING * (Math.abs(min) + Math.abs(max) + Math.abs(centre[k]));
            if (Float.isInfinite(inverse[k])) { // the rays do not move along axis k
                if (min - grow > centre[k] || max + grow < centre[k]) {
                    return MISS;
                }
                continue;
            }
            float t0 = (min - grow - centre[k]) * inverse[k];
            float t1 = (max + grow - centre[k]) * inverse[k];
            enter = FastMath.max(enter, FastMath.min(t0, t1));
            exit = FastMath.min(exit, FastMath.max(t0, t1));
        }
        return enter <= exit && exit >= 0 ? enter : MISS;
    }
}
