package rtd.accel;

import java.util.Map;
import java.util.TreeMap;
import rtd.geometry.IGeometry;

/**
 * The intersection tests that one {@link NearestHit} has run, in all and by kind of object: what
 * {@code --stats} reports per ray and {@code --view cost} draws. Not the paper's: counting is all
 * it does, and it never changes which object a ray hits.
 *
 * <p>Counted as cheaply as the tests allow, as they are counted on every ray: the objects tested
 * at their places (a grid's cells) one by one; a leaf's objects at once if they are all of one
 * kind; and for a leaf of several kinds, only how many rays tested it, sorted by kind when asked
 * ({@link #byKind}).
 */
final class TestCounts {

    private final Bvh bvh;
    private final LeafObjects leaves;
    /** The tests by kind, where the tree holds more than one kind; else only {@link #treeTests} counts. */
    private final long[] tests;
    /**
     * Per leaf of several kinds ({@link Bvh#mixedLeaves}), how many rays tested its objects: not one
     * counter a node, which for a mesh of a million triangles would be megabytes a tracer.
     */
    private final long[] leafVisits;
    private final boolean severalKinds;
    /** The tests of the tree's objects so far. */
    private long treeTests;
    /** The rays that tested every object without a box. */
    private long unboundedTests;

    TestCounts(Bvh bvh) {
        this.bvh = bvh;
        this.leaves = bvh.leaves;
        this.tests = new long[leaves.kindNames.length];
        this.leafVisits = new long[bvh.mixedLeaves.length];
        this.severalKinds = tests.length > 1;
    }

    /** One ray tested the {@code objects} objects of {@code leaf}. */
    void leaf(int leaf, int objects) {
        treeTests += objects;
        if (severalKinds) {
            int kind = bvh.leafKinds[leaf];
            if (kind >= 0) {
                tests[kind] += objects;
            } else {
                leafVisits[-1 - kind]++;
            }
        }
    }

    /** One ray tested the object at {@code place} in leaf order. */
    void place(int place) {
        treeTests++;
        if (severalKinds) {
            tests[leaves.kinds[place]]++;
        }
    }

    /** One ray tested every object without a box. */
    void unbounded() {
        unboundedTests++;
    }

    /** The tests of the tree's objects by kind ({@link LeafObjects#kindNames}). */
    long[] byKind() {
        if (tests.length == 1) {
            return new long[] {treeTests}; // one kind: counted per leaf only
        }
        long[] byKind = tests.clone();
        for (int m = 0; m < leafVisits.length; m++) {
            if (leafVisits[m] > 0) {
                int leaf = bvh.mixedLeaves[m];
                int first = bvh.nodes[2 * leaf];
                for (int i = first; i < first + bvh.nodes[2 * leaf + 1]; i++) {
                    byKind[leaves.kinds[i]] += leafVisits[m];
                }
            }
        }
        return byKind;
    }

    /** The tests so far by the name of each kind of object, those of the objects without a box too ({@code --stats}). */
    Map<String, Long> byKindName() {
        Map<String, Long> tests = new TreeMap<>();
        long[] treeTests = byKind();
        for (int k = 0; k < treeTests.length; k++) {
            tests.merge(leaves.kindNames[k], treeTests[k], Long::sum);
        }
        for (IGeometry object : bvh.unbounded) {
            tests.merge(object.kind(), unboundedTests, Long::sum);
        }
        return tests;
    }

    /** How many counters of leaf visits these counts keep. */
    int leafCounters() {
        return leafVisits.length;
    }

    /** All tests so far: a running count, read before and after a ray to tell its own. */
    long all() {
        return treeTests + unboundedTests * bvh.unbounded.length;
    }

}
