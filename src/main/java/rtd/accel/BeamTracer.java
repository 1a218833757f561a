package rtd.accel;

import java.util.Arrays;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Sphere;
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
 * find a nearer hit. It is written out again here, not shared with {@link BvhTracer}
 * through an interface: measured on 2026-12-01, one walk for both cost 7 % of the render of a
 * million spheres and 11 % of a million-triangle mesh, the price of a call the JIT cannot bind to
 * one class in the innermost loop. At a leaf, each ray that enters the leaf's box no farther than its own
 * nearest hit runs the paper's tests on the leaf's objects ({@link NearestHit}).
 *
 * <p>Two answers need no ray at all. A beam that reaches no object's box misses everywhere: a
 * square, or a whole run of squares ({@link #traceAtOnce}), is background. And when the
 * shader reads only which object a ray hits (the paper's flat colours), a square, or a run,
 * inside the outline of the one sphere in its reach is that sphere throughout
 * ({@link #coveredBySphere}).
 */
final class BeamTracer {

    private static final float MISS = NearestHit.MISS;

    private final Bvh bvh;
    private final int[] stackNodes;
    private final float[] stackEntries;
    private final float[] stackExits;
    private final Beam beam = new Beam();
    /** The beam's middle ray, which tests the boxes for all its rays. */
    private final MiddleRay middle;
    /** The rays of the square and their nearest hits; reused from square to square. */
    private NearestHit[] hits = new NearestHit[0];
    /** Each ray's count of tests before this square, so that each ray's own tests can be told ({@code --view cost}). */
    private long[] testsBefore = new long[0];
    private int count;
    /** Whether the rays' hits are started; not before a leaf's objects are in reach, unless the scene has planes. */
    private boolean started;
    /**
     * Whether the walk only asks if the beam reaches no object, or only a sphere that covers it
     * ({@link #traceAtOnce}), and makes no rays.
     */
    private boolean probing;
    /**
     * Whether a sphere could cover this square ({@link #coveredBySphere}): not unless the rays
     * are parallel, only the object is asked for, and the tree's largest sphere is wider than
     * the square. Not asked where it cannot pay (a million small spheres), the check drops out of
     * the code the JIT compiles: with it, their first render took 0.4 s longer.
     */
    private boolean coverable;
    /** The largest squared radius of the tree's spheres. */
    private final float largestSphereSquared;
    /**
     * The sphere (its place among the leaves' objects) that every ray of the square hits, found
     * before any ray is made ({@link #coveredBySphere}); else −1.
     */
    private int covering = -1;
    /** The leaf of {@link #covering}, its growth and its t bound, where its rays are traced after all if another object is in reach. */
    private int coveringLeaf;
    private float coveringGrow;
    private float coveringWithin;
    private RayBundle bundle;
    /** The farthest of the rays' {@link NearestHit#skipBeyond}: no box beyond it can matter. */
    private float farthestSkip;
    private long rays;
    private long nodesVisited;

    BeamTracer(Bvh bvh) {
        this.bvh = bvh;
        this.middle = new MiddleRay(bvh, beam);
        this.largestSphereSquared = bvh.leaves.largestSphereSquared();
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
        count = bundle.count();
        if (hits.length < count) { // the old ones keep their counts of tests
            int old = hits.length;
            hits = Arrays.copyOf(hits, count);
            for (int i = old; i < count; i++) {
                hits[i] = new NearestHit(bvh);
            }
        }
        if (testsBefore.length < count) {
            testsBefore = new long[count];
        }
        this.bundle = bundle;
        started = false;
        coverable = isCoverable(out);
        covering = -1;
        farthestSkip = Float.POSITIVE_INFINITY;
        if (bvh.unbounded.length > 0) {
            start();
        }
        if (bvh.hasTree()) {
            walk();
        }
        rays += count;
        if (covering >= 0) {
            out.setHits(bvh.leaves.fileOrder[covering], count); // inside the sphere's outline: no ray was needed
            covering = -1;
            return true;
        }
        if (!started) {
            out.setMisses(count); // the beam reached no object: no ray was needed
            return true;
        }
        for (int i = 0; i < count; i++) {
            out.set(i, hits[i].best(), hits[i].bestT(), hits[i].bestDistance());
            out.setTests(i, hits[i].testsRun() - testsBefore[i]);
        }
        return true;
    }

    /**
     * Whether every ray of the bundle's parallel rays has the same answer, found by the walk
     * alone, without making a ray: the beam reaches no object (every ray misses), or, when only
     * the object is asked for ({@link HitBuffer#hitPointsRead}), it lies inside the outline of
     * the one sphere in its reach (every ray hits that sphere first). Then the answer is in
     * {@code out}, the rays count as traced, and the answer is true. False if the rays' answers
     * may differ, if the scene has objects without a box (which every ray meets), or if the
     * rays are not the orthographic camera's. The bundle may be any rectangle of pixels, as the
     * corners of any rectangle hold its origins ({@link Beam#aimAt}).
     */
    boolean traceAtOnce(RayBundle bundle, HitBuffer out) {
        if (bvh.unbounded.length > 0 || !(bundle.camera() instanceof OrthographicCamera) || !middle.aim(bundle)) {
            return false; // other bundles are parallel seldom, and telling would make all their rays
        }
        started = false;
        covering = -1;
        coverable = isCoverable(out);
        farthestSkip = Float.POSITIVE_INFINITY;
        if (bvh.hasTree()) {
            probing = true;
            walk();
            probing = false;
        }
        int covered = covering;
        covering = -1;
        if (started) {
            return false;
        }
        rays += bundle.count();
        if (covered >= 0) {
            out.setHits(bvh.leaves.fileOrder[covered], bundle.count());
        } else {
            out.setMisses(bundle.count());
        }
        return true;
    }

    /**
     * Whether a sphere could cover the beam ({@link #coveredBySphere}): not unless the rays are
     * parallel, only the object is asked for, and the tree's largest sphere is wider than the
     * beam.
     */
    private boolean isCoverable(HitBuffer out) {
        return !out.hitPointsRead() && middle.parallel && largestSphereSquared
                > middle.half[0] * middle.half[0] + middle.half[1] * middle.half[1] + middle.half[2] * middle.half[2];
    }

    /** Starts each ray's nearest hit, with the objects that have no box, which every ray meets. */
    private void start() {
        bundle.make();
        farthestSkip = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            NearestHit hit = hits[i];
            testsBefore[i] = hit.testsRun();
            hit.start(bundle.originX(i), bundle.originY(i), bundle.originZ(i),
                    bundle.directionX(i), bundle.directionY(i), bundle.directionZ(i));
            hit.testUnbounded();
            farthestSkip = FastMath.max(farthestSkip, hit.skipBeyond());
        }
        started = true;
    }

    /** The work done so far: rays, intersection tests, and nodes visited by walks and by rays at leaves. */
    WorkCount work() {
        long[] tests = new long[bvh.leaves.kindNames.length];
        long unbounded = 0;
        for (NearestHit hit : hits) {
            long[] counts = hit.tests();
            for (int k = 0; k < tests.length; k++) {
                tests[k] += counts[k];
            }
            unbounded += hit.unboundedTests();
        }
        return new WorkCount(rays, BvhTracer.testsByKind(bvh, tests, unbounded), nodesVisited);
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
        float reach = objectsEntry(leaf, grow, within);
        if (!worthVisiting(reach)) {
            return;
        }
        if (probing) { // an object in reach: the rays' answers differ unless it is a sphere that covers the beam
            if (covering < 0 && coverable && coveredBySphere(leaf, grow, within)) {
                return; // the walk goes on, for any other object in reach before the sphere's hits
            }
            started = true;
            farthestSkip = Float.NEGATIVE_INFINITY;
            return;
        }
        if (!started) {
            if (covering < 0 && coverable && coveredBySphere(leaf, grow, within)) {
                return;
            }
            start();
            if (covering >= 0) { // another object in reach after all: the rays are traced, in the sphere's leaf too
                int putOff = coveringLeaf;
                covering = -1;
                testRays(putOff, objectsEntry(putOff, coveringGrow, coveringWithin), coveringGrow);
            }
        }
        testRays(leaf, reach, grow);
    }

    /**
     * Whether the beam reaches only one object of the leaf, a sphere that every ray of the
     * square surely hits ({@link SphereOutline#everyRayHitsBefore}): then no ray need be traced, as long
     * as the walk meets no other object in reach before the sphere's hits. The walk goes on,
     * skipping the boxes beyond them; if it meets another object in reach, the rays are traced
     * after all, in the sphere's leaf too ({@link #testLeaf}). Asked only of parallel rays ({@link #coverable}).
     */
    private boolean coveredBySphere(int leaf, float grow, float within) {
        int only = onlyObjectInReach(leaf, grow, within);
        if (only < 0 || !(bvh.objects.get(bvh.leaves.fileOrder[only]) instanceof Sphere sphere)) {
            return false;
        }
        double before = SphereOutline.everyRayHitsBefore(sphere, beam.lowest, beam.highest, beam.dx, beam.dy, beam.dz);
        if (!(before >= 0)) {
            return false;
        }
        double origins = Math.sqrt(square(Math.abs(middle.centre[0]) + middle.half[0])
                + square(Math.abs(middle.centre[1]) + middle.half[1]) + square(Math.abs(middle.centre[2]) + middle.half[2]));
        covering = only;
        coveringLeaf = leaf;
        coveringGrow = grow;
        coveringWithin = within;
        // a ray's skip distance for a hit there (NearestHit.skipFor), generously: boxes beyond cannot hold a nearer hit
        farthestSkip = (float) (before * (1 + 1e-4) + 1e-4 * origins / middle.shortest);
        return true;
    }

    private static double square(double x) {
        return x * x;
    }

    /** The one object of the leaf whose box the beam reaches, or −1 if none or several do. */
    private int onlyObjectInReach(int leaf, float grow, float within) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        int only = -1;
        for (int i = first; i < end; i++) {
            if (worthVisiting(objectEntry(i, grow, within))) {
                if (only >= 0) {
                    return -1;
                }
                only = i;
            }
        }
        return only;
    }

    /**
     * Each ray that could find a nearer hit in the leaf, whose objects the beam enters at
     * {@code reach}, runs the paper's tests there.
     */
    private void testRays(int leaf, float reach, float grow) {
        float farthest = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            NearestHit hit = hits[i];
            if (reach <= hit.skipBeyond()) {
                nodesVisited++;
                if (hit.worthVisiting(hit.entry(leaf, grow))) {
                    hit.testLeaf(leaf);
                }
            }
            farthest = FastMath.max(farthest, hit.skipBeyond());
        }
        farthestSkip = farthest;
    }

    /** The beam's entry into the nearest box of the leaf's objects, or {@link #MISS} if it reaches none. */
    private float objectsEntry(int leaf, float grow, float within) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        float entry = MISS;
        for (int i = first; i < end; i++) {
            entry = FastMath.min(entry, objectEntry(i, grow, within));
        }
        return entry;
    }

    /**
     * The beam's entry into the box of the leaves' object {@code i}, or {@link #MISS} if it
     * reaches none, or if the object is a sphere that no ray of the square hits (a square in
     * the corner of a sphere's box, outside its outline).
     */
    private float objectEntry(int i, float grow, float within) {
        float entry = middle.grownEntry(bvh.leaves.boxes, 6 * i, grow, within);
        return entry < MISS && middle.parallel
                && bvh.leaves.missedByEvery(i, middle.cornerWorthy, beam.lowest, beam.highest, beam.dx, beam.dy, beam.dz)
                ? MISS : entry;
    }

}
