package rtd.accel;

import java.util.Map;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.DepthTest;

/**
 * One ray, kept as numbers, and the nearest hit found for it so far: the state of the paper's
 * depth test (Listing 4.3) while a tracer visits the leaves of a {@link Bvh} in some order, or
 * the objects of a {@link ViewGrid}'s cell ({@link #testPlacesNearestFirst}).
 *
 * <p>{@link #testLeaf} runs the paper's intersection test and depth test unchanged: the hit
 * nearest to the origin ({@code |P − O|}) wins, and on a tie the object that comes first in
 * the file. So the order in which leaves are visited does not change the answer; a tracer
 * only must not skip a leaf in which the ray could find a nearer hit ({@link #worthVisiting}).
 *
 * <p>Boxes are grown as the ray runs: an object's test may report a hit outside its box by
 * a margin that grows with the distance the ray has run ({@link Rounding}). A walk knows a t
 * beyond which the ray cannot be in a node (its {@link #reach}, then each parent's exit), and
 * grows the node's children by their margin there ({@link #growth}).
 *
 * <p>Kept as numbers, and reused from ray to ray, because a {@link Ray} kept in a field
 * would be allocated for every ray.
 */
final class NearestHit {

    /**
     * How much farther than the nearest hit a box may start and still be visited. Distances
     * and box entries round differently; this margin (relative, and relative to the origin's
     * size) keeps a box whose object could tie or win by a rounding error.
     */
    private static final float SKIP_MARGIN = 1e-5f;
    static final float MISS = Float.POSITIVE_INFINITY; // the entry of a box the ray misses

    private final Bvh bvh;
    private final LeafObjects leaves;
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
    /** |R|: a box grows with the distance {@code t·|R|} the ray has run. */
    private float length;
    private float margin;
    private int best;
    /** The nearest hit's place in leaf order ({@link LeafObjects}), −1 if it is none of the tree's objects. */
    private int bestPlace;
    private float bestT;
    private float bestDistance;
    /** The nearest hit's {@link DepthTest}: a hit with a smaller key wins the depth test. */
    private long bestKey;
    private float skipBeyond;
    private float exit; // of the box of the last entry()
    /** The intersection tests run for this object's rays, for {@code --stats} and {@code --view cost}. */
    private final TestCounts counts;
    private final UnboundedObjects unbounded;

    NearestHit(Bvh bvh) {
        this.bvh = bvh;
        this.leaves = bvh.leaves;
        this.counts = new TestCounts(bvh);
        this.unbounded = new UnboundedObjects(bvh.unbounded);
    }

    /** Starts on a new ray {@code O + t·D}, with no hit yet. */
    void start(float originX, float originY, float originZ, float directionX, float directionY, float directionZ) {
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
        length = (float) Math.sqrt(dd);
        margin = SKIP_MARGIN * (float) Math.sqrt(ox * ox + oy * oy + oz * oz) / length;
        best = -1;
        bestPlace = -1;
        bestT = Float.NaN;
        bestDistance = Float.POSITIVE_INFINITY;
        bestKey = DepthTest.NO_HIT;
        skipBeyond = Float.POSITIVE_INFINITY;
    }

    /** {@link #start} on {@code ray}'s numbers. */
    void start(Ray ray) {
        Vector3f origin = ray.origin();
        Vector3f direction = ray.direction();
        start(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
    }

    /**
     * Looks only for hits nearer than {@code distance} from the origin: boxes the ray enters
     * beyond it are skipped, as they are beyond a nearest hit.
     */
    void limitTo(float distance) {
        float t = distance / length;
        bestDistance = distance;
        bestKey = distance >= 0 ? DepthTest.key(distance, 0) : Long.MIN_VALUE; // a hit at the limit, or beyond, loses
        skipBeyond = skipFor(t);
    }

    /** A t beyond which no object of the tree can report a hit ({@link Bvh#reach}). */
    float reach() {
        return bvh.reach(ox, oy, oz, length);
    }

    /** How much to grow {@code node}'s children for a ray not in it beyond {@code reach} ({@link Bvh#growth}). */
    float growth(int node, float reach) {
        return bvh.growth(node, reach * length);
    }

    /**
     * The slab test of the box of {@code node} grown by {@code grow}: the t at which the ray
     * enters it, or {@link #MISS}; negative when the origin lies inside. {@link #worthVisiting}
     * refuses a NaN as it does a miss. {@link #exit} gives where it leaves.
     */
    float entry(int node, float grow) {
        float[] bounds = bvh.boxes;
        int at = Bvh.BOX * node;
        float x0 = (bounds[at] - grow - ox) * ix;
        float x1 = (bounds[at + 3] + grow - ox) * ix;
        float y0 = (bounds[at + 1] - grow - oy) * iy;
        float y1 = (bounds[at + 4] + grow - oy) * iy;
        float z0 = (bounds[at + 2] - grow - oz) * iz;
        float z1 = (bounds[at + 5] + grow - oz) * iz;
        float enter = FastMath.max(FastMath.max(FastMath.min(x0, x1), FastMath.min(y0, y1)), FastMath.min(z0, z1));
        exit = FastMath.min(FastMath.min(FastMath.max(x0, x1), FastMath.max(y0, y1)), FastMath.max(z0, z1));
        return FastMath.max(enter, 0) <= exit ? enter : MISS; // entered no later than left, and not left behind
    }

    /** Where the ray leaves the box of the last {@link #entry}. */
    float exit() {
        return exit;
    }

    /**
     * Whether the ray enters a box ({@code entry} finite) no farther than the nearest hit allows.
     * One comparison, as a missed box's entry (infinite) lies beyond the largest float: a branch
     * that the first rays never take would make the JIT compile the walk again when one does.
     */
    boolean worthVisiting(float entry) {
        return entry <= FastMath.min(skipBeyond, Float.MAX_VALUE);
    }

    /** Boxes that the ray enters beyond this t cannot hold a nearer hit (infinite while there is none). */
    float skipBeyond() {
        return skipBeyond;
    }

    /** The paper's intersection test and depth test on a leaf's objects. */
    void testLeaf(int leaf) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        counts.leaf(first, end);
        for (int i = first; i < end; i++) {
            test(i);
        }
    }

    /**
     * The paper's intersection test and depth test on the objects at these places in leaf order;
     * a place of −1 is passed over.
     */
    void testPlaces(int[] places) {
        for (int place : places) {
            if (place >= 0) {
                counts.place(place);
                test(place);
            }
        }
    }

    /**
     * The paper's intersection test and depth test on the objects at places
     * {@code places[from .. to)} in leaf order (a {@link ViewGrid}'s cell), in the order of
     * {@code nearest}, growing, a distance from the ray's origin within which no hit on the object
     * lies: the tests stop at the first place where that passes the nearest hit, by more than
     * rounding can explain, as all after it do.
     */
    void testPlacesNearestFirst(int[] places, int from, int to, float[] nearest) {
        for (int k = from; k < to; k++) {
            int place = places[k];
            if (nearest[place] > skipBeyond * length) {
                return;
            }
            counts.place(place);
            test(place);
        }
    }

    /**
     * The paper's intersection test and depth test on the objects at places
     * {@code places[from .. to)} in leaf order, until one is hit: a shadow ray's question
     * ({@link #limitTo} first), which any hit answers. The places come in the order of
     * {@code nearest}, a distance from the light before which no hit on the object lies, growing
     * along them; the tests stop at the first place beyond {@code farthest}, the farthest from
     * the light that a hit of the ray can lie.
     */
    void testPlacesUntilHit(int[] places, int from, int to, float[] nearest, float farthest) {
        for (int k = from; k < to && best < 0; k++) {
            int place = places[k];
            if (nearest[place] > farthest) {
                return;
            }
            counts.place(place);
            test(place);
        }
    }

    /** The paper's intersection test and depth test on the object at place {@code i} in leaf order. */
    private void test(int i) {
        float t = leaves.t(i, ox, oy, oz, dx, dy, dz, dd);
        if (t >= 0) { // false for NaN: no hit
            consider(leaves.fileOrder[i], i, t, LeafObjects.distance(t, ox, oy, oz, dx, dy, dz));
        }
    }

    /** The paper's tests on the objects without a box, which every ray meets. */
    void testUnbounded() {
        int count = unbounded.count();
        if (count == 0) {
            return;
        }
        counts.unbounded();
        for (int i = 0; i < count; i++) {
            float t = unbounded.t(i, ox, oy, oz, dx, dy, dz);
            if (t >= 0) { // false for NaN: no hit
                consider(bvh.unboundedOrder[i], -1, t, LeafObjects.distance(t, ox, oy, oz, dx, dy, dz));
            }
        }
    }

    /** The depth test: the nearest hit wins, and on a tie the one that comes first in the file ({@link DepthTest}). */
    private void consider(int index, int place, float t, float distance) {
        long key = DepthTest.key(distance, index);
        if (key < bestKey) {
            best = index;
            bestPlace = place;
            bestT = t;
            bestDistance = distance;
            bestKey = key;
            skipBeyond = skipFor(t);
        }
    }

    /** Boxes entered beyond a hit at {@code t}, by more than rounding can explain, cannot hold a nearer one. */
    private float skipFor(float t) {
        return t + t * SKIP_MARGIN + margin;
    }

    /** The nearest hit found for {@code ray} (the ray these numbers are of) as a hit record, or null if none. */
    Hit hit(Ray ray) {
        if (best < 0) {
            return null;
        }
        return new Hit(bvh.objects.get(best), best, bestT, bestDistance, ray.pointAt(bestT));
    }

    /** The place in the file of the nearest object hit, or −1. */
    int best() {
        return best;
    }

    /** The nearest hit's place in leaf order, −1 if none or if it is an object without a box. */
    int bestPlace() {
        return bestPlace;
    }

    /** The t of the nearest hit, NaN if none. */
    float bestT() {
        return bestT;
    }

    /** The distance {@code |P − O|} of the nearest hit, infinite if none. */
    float bestDistance() {
        return bestDistance;
    }

    /** Intersection tests run for this object's rays so far, by the name of each kind of object ({@code --stats}). */
    Map<String, Long> testsByKind() {
        return counts.byKindName();
    }

    /** All intersection tests run for this object's rays so far: a running count, read before and after a ray. */
    long testsRun() {
        return counts.all();
    }
}
