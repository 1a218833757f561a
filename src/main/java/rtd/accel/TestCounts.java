package rtd.accel;

import java.util.Map;
import java.util.TreeMap;
import rtd.geometry.IGeometry;

/**
 * The intersection tests that one {@link NearestHit} has run, in all and by kind of object: what
 * {@code --stats} reports per ray and {@code --view cost} draws. Counting is all it does, and it
 * never changes which object a ray hits. Where the tree holds one kind of object, as most scenes
 * do, a leaf's tests are counted at once; else each by its object's kind.
 */
final class TestCounts {

    private final LeafObjects leaves;
    private final IGeometry[] unbounded;
    /** The tests by kind ({@link LeafObjects#kindNames}), where the tree holds several kinds. */
    private final long[] tests;
    private final boolean severalKinds;
    /** The tests of the tree's objects so far. */
    private long treeTests;
    /** The rays that tested every object without a box. */
    private long unboundedTests;

    TestCounts(Bvh bvh) {
        this.leaves = bvh.leaves;
        this.unbounded = bvh.unbounded;
        this.tests = new long[leaves.kindNames.length];
        this.severalKinds = tests.length > 1;
    }

    /** One ray tested the objects at places {@code [first, end)} in leaf order. */
    void leaf(int first, int end) {
        treeTests += end - first;
        if (severalKinds) {
            for (int i = first; i < end; i++) {
                tests[leaves.kinds[i]]++;
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

    /** The tests so far by the name of each kind of object, the objects without a box too ({@code --stats}). */
    Map<String, Long> byKindName() {
        return byName(leaves.kindNames, severalKinds ? tests : new long[] {treeTests}, unbounded, unboundedTests);
    }

    /** {@code tests[k]} by the name {@code names[k]}; {@code unboundedTests} by each boxless object's kind. */
    static Map<String, Long> byName(String[] names, long[] tests, IGeometry[] unbounded, long unboundedTests) {
        Map<String, Long> byName = new TreeMap<>();
        for (int k = 0; k < names.length; k++) {
            byName.merge(names[k], tests[k], Long::sum);
        }
        for (IGeometry object : unbounded) {
            byName.merge(object.kind(), unboundedTests, Long::sum);
        }
        return byName;
    }

    /** All tests so far: a running count, read before and after a ray to tell its own. */
    long all() {
        return treeTests + unboundedTests * unbounded.length;
    }
}
