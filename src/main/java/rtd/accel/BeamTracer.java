package rtd.accel;

import java.util.Map;
import rtd.camera.OrthographicCamera;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.WorkCount;

/**
 * Traces the rays of a square of pixels together through a {@link Bvh}. Not in the paper: it
 * serves the cameras, whose rays in a square are alike: the orthographic camera's all share one
 * direction, the perspective camera's all start at the eye and differ in direction by a few
 * thousandths ({@link Beam}).
 *
 * <p>Rays from origins within C ± h, with directions within D ± s, form a beam, whose middle
 * ray's tests of grown boxes ({@link MiddleRay}) answer for every ray of the square: one walk
 * down the tree visits every box that any ray of the square enters.
 *
 * <p>The walk is {@link BvhTracer}'s walk for one ray, with the beam's grown boxes in place
 * of the ray's boxes, and the farthest of the rays' nearest hits in place of the ray's own: it
 * goes nearer child first and skips every box the beam enters beyond that, where no ray can
 * find a nearer hit. It is written out again here rather than shared with {@link BvhTracer}
 * through an interface, so that the innermost loop makes no call the JIT cannot bind to one
 * class. At a leaf, each ray that enters the leaf's box no farther than its own nearest hit
 * runs its shape's own test on the leaf's objects ({@link NearestHit}).
 *
 * <p>One answer needs no ray at all: a beam that reaches no object's box misses everywhere, so a
 * square, or a whole run of squares ({@link #traceAtOnce}), is background. Every other answer
 * comes from the shapes' own tests, so an edited or a new shape is drawn as its test says.
 *
 * <p>The rays themselves, made only once the walk reaches an object, are {@link BeamRays}.
 */
final class BeamTracer {

    private final Bvh bvh;
    private final int[] stackNodes;
    private final float[] stackEntries;
    private final float[] stackExits;
    private final Beam beam = new Beam();
    /** The beam's middle ray, which tests the boxes for all its rays. */
    private final MiddleRay middle;
    /** The rays of the square and their nearest hits; reused from square to square. */
    private final BeamRays squareRays;
    private RayBundle bundle;
    /** Whether the rays are started; not before a leaf's objects are in reach, unless the scene has planes. */
    private boolean started;
    /** Whether the walk only asks if the beam reaches no object ({@link #traceAtOnce}), and makes no rays. */
    private boolean probing;
    /** The farthest of the rays' {@link NearestHit#skipBeyond}: no box beyond it can matter. */
    private float farthestSkip;
    private long rays;
    private long nodesVisited;

    BeamTracer(Bvh bvh) {
        this.bvh = bvh;
        this.middle = new MiddleRay(bvh, beam);
        this.squareRays = new BeamRays(bvh);
        this.stackNodes = new int[bvh.maxDepth + 2];
        this.stackEntries = new float[bvh.maxDepth + 2];
        this.stackExits = new float[bvh.maxDepth + 2];
    }

    /**
     * Traces the bundle's rays into {@code out} if they form a beam; false, having traced
     * nothing, if they are too unlike, or too far out for float to hold the beam's size.
     */
    boolean trace(RayBundle bundle, HitBuffer out) {
        if (!middle.aim(bundle)) {
            return false;
        }
        int count = bundle.count();
        squareRays.prepare(count);
        this.bundle = bundle;
        started = false;
        farthestSkip = Float.POSITIVE_INFINITY;
        if (bvh.unbounded.length > 0) {
            start();
        }
        if (bvh.hasTree()) {
            walk();
        }
        rays += count;
        if (!started) {
            out.setMisses(count); // the beam reached no object: no ray was needed
            return true;
        }
        squareRays.writeTo(out);
        return true;
    }

    /**
     * Whether the beam of the bundle's parallel rays reaches no object's box, found by the walk
     * alone, without making a ray: then every ray misses, that answer is in {@code out}, the rays
     * count as traced, and the answer is true. False if some ray may hit, if the scene has
     * objects without a box (which every ray meets), or if the rays are not the orthographic
     * camera's. The bundle may be any rectangle of pixels, as the corners of any rectangle hold
     * its origins ({@link Beam#aimAt}).
     */
    boolean traceAtOnce(RayBundle bundle, HitBuffer out) {
        if (bvh.unbounded.length > 0 || !(bundle.camera() instanceof OrthographicCamera) || !middle.aim(bundle)) {
            return false; // other bundles are parallel seldom, and telling would make all their rays
        }
        started = false;
        farthestSkip = Float.POSITIVE_INFINITY;
        if (bvh.hasTree()) {
            probing = true;
            walk();
            probing = false;
        }
        if (started) {
            return false;
        }
        rays += bundle.count();
        out.setMisses(bundle.count());
        return true;
    }

    /** Starts the rays, with the objects that have no box, which every ray meets. */
    private void start() {
        farthestSkip = squareRays.start(bundle);
        started = true;
    }

    /** The work done so far: rays, intersection tests, and nodes visited by walks and by rays at leaves. */
    WorkCount work() {
        Map<String, Long> tests = squareRays.testsByKind();
        return new WorkCount(rays, tests, nodesVisited + squareRays.leafVisits());
    }

    /** Walks down the tree, nearer child first, skipping boxes entered beyond every ray's nearest hit. */
    private void walk() {
        int[] nodes = bvh.nodes;
        float reach = BoxGrowth.reach(bvh, middle.centre[0], middle.centre[1], middle.centre[2],
                middle.half[0], middle.half[1], middle.half[2], middle.shortest);
        int stackSize = 0;
        int node = 0;
        nodesVisited++;
        if (!worthVisiting(middle.grownEntry(bvh.boxes, Bvh.BOX * node, growth(node, reach), reach))) {
            return;
        }
        float nodeExit = FastMath.min(middle.exit, reach);
        while (true) {
            int first = nodes[2 * node];
            if (nodes[2 * node + 1] != Bvh.INNER) {
                testLeaf(node, growth(node, nodeExit), nodeExit);
            } else {
                nodesVisited += 2;
                float grow = growth(node, nodeExit);
                int near = first;
                int far = first + 1;
                float nearEntry = middle.grownEntry(bvh.boxes, Bvh.BOX * near, grow, nodeExit);
                float nearExit = FastMath.min(middle.exit, nodeExit);
                float farEntry = middle.grownEntry(bvh.boxes, Bvh.BOX * far, grow, nodeExit);
                float farExit = FastMath.min(middle.exit, nodeExit);
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
                if (worthVisiting(farEntry)) {
                    stackNodes[stackSize] = far;
                    stackEntries[stackSize] = farEntry;
                    stackExits[stackSize] = farExit;
                    stackSize++;
                }
                if (worthVisiting(nearEntry)) {
                    node = near;
                    nodeExit = nearExit;
                    continue;
                }
            }
            do {
                if (stackSize == 0) {
                    return;
                }
                stackSize--;
                node = stackNodes[stackSize];
                nodeExit = stackExits[stackSize];
            } while (stackEntries[stackSize] > farthestSkip);
        }
    }

    /** As {@link NearestHit#worthVisiting}, for the farthest of the rays' nearest hits. */
    private boolean worthVisiting(float entry) {
        return entry <= FastMath.min(farthestSkip, Float.MAX_VALUE);
    }

    /** The rounding margin of {@code node}'s objects for rays not beyond {@code reach}: the same for every ray of the beam. */
    private float growth(int node, float reach) {
        return BoxGrowth.growth(bvh.boxes, node, reach * middle.longest);
    }

    /**
     * Runs the paper's tests on the leaf's objects for each ray that could find a nearer hit
     * there. {@code reach}, the beam's entry into the nearest of the objects' boxes, is a t
     * before which no ray of the square hits any of them.
     */
    private void testLeaf(int leaf, float grow, float within) {
        float reach = middle.objectsEntry(leaf, grow, within);
        if (!worthVisiting(reach)) {
            return;
        }
        if (probing) { // an object in reach: some ray may hit it, so the probe ends
            started = true;
            farthestSkip = Float.NEGATIVE_INFINITY;
            return;
        }
        if (!started) {
            start();
        }
        testRays(leaf, reach, grow);
    }

    /** Each ray that could find a nearer hit in the leaf, whose objects the beam enters at {@code reach}, runs the paper's tests there. */
    private void testRays(int leaf, float reach, float grow) {
        farthestSkip = squareRays.testLeaf(leaf, reach, grow);
    }
}
