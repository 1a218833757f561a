package rtd.accel;

import java.util.Arrays;
import java.util.Map;
import java.util.TreeMap;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;

/**
 * The rays of one square that a {@link BeamTracer} walks down the tree together, each with its
 * own nearest hit so far ({@link NearestHit}): started only once the walk reaches an object,
 * tested at each leaf the beam enters, and read out into the hit buffer at the end. Reused from
 * square to square, so that a square makes no garbage. Not in the paper.
 */
final class BeamRays {

    private final Bvh bvh;
    /** The rays' nearest hits; each keeps its counts of tests from square to square. */
    private NearestHit[] hits = new NearestHit[0];
    /** Each ray's count of tests before this square, so that each ray's own tests can be told ({@code --view cost}). */
    private long[] testsBefore = new long[0];
    private int count;
    /** The leaves visited ray by ray, which count as nodes visited. */
    private long leafVisits;

    BeamRays(Bvh bvh) {
        this.bvh = bvh;
    }

    /** Makes room for a square of {@code count} rays; none is started yet. */
    void prepare(int count) {
        this.count = count;
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
    }

    /**
     * Makes the bundle's rays and starts each one's nearest hit with the objects that have no
     * box, which every ray meets; the farthest of their {@link NearestHit#skipBeyond}.
     */
    float start(RayBundle bundle) {
        bundle.make();
        float farthestSkip = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            NearestHit hit = hits[i];
            testsBefore[i] = hit.testsRun();
            hit.start(bundle.originX(i), bundle.originY(i), bundle.originZ(i),
                    bundle.directionX(i), bundle.directionY(i), bundle.directionZ(i));
            hit.testUnbounded();
            farthestSkip = FastMath.max(farthestSkip, hit.skipBeyond());
        }
        return farthestSkip;
    }

    /**
     * Each ray that could find a nearer hit in the leaf, whose objects the beam enters at
     * {@code reach}, runs the paper's tests there; the farthest of the rays' skip distances after.
     */
    float testLeaf(int leaf, float reach, float grow) {
        float farthest = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            NearestHit hit = hits[i];
            if (reach <= hit.skipBeyond()) {
                leafVisits++;
                if (hit.worthVisiting(hit.entry(leaf, grow))) {
                    hit.testLeaf(leaf);
                }
            }
            farthest = FastMath.max(farthest, hit.skipBeyond());
        }
        return farthest;
    }

    /** Writes each ray's nearest hit and its count of tests in this square into {@code out}. */
    void writeTo(HitBuffer out) {
        for (int i = 0; i < count; i++) {
            out.set(i, hits[i].best(), hits[i].bestT(), hits[i].bestDistance());
            out.setTests(i, hits[i].testsRun() - testsBefore[i]);
        }
    }

    /** The leaves visited ray by ray so far. */
    long leafVisits() {
        return leafVisits;
    }

    /** The intersection tests of all the rays so far, by kind of object. */
    Map<String, Long> testsByKind() {
        Map<String, Long> tests = new TreeMap<>();
        for (NearestHit hit : hits) {
            hit.testsByKind().forEach((kind, count) -> tests.merge(kind, count, Long::sum));
        }
        return tests;
    }
}
