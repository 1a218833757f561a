package rtd.accel;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The objects of a {@link Bvh}'s leaves, in leaf order, so that the objects of a leaf lie next
 * to each other in memory: each one's place in the scene file (for the depth test's tie rule),
 * its box, and, for spheres and triangles, the numbers of its intersection test packed into one
 * array.
 *
 * <p>{@link #t} runs {@link Sphere#intersect} (equations 3.6 to 3.8) and {@link Triangle#hit}
 * on these numbers, with the same float operations in the same order, so it finds the same
 * {@code t} to the last bit; it only skips following references. With a million objects this
 * matters: a reference to each object and its corners is a wait for memory per test, while the
 * numbers of a leaf's objects arrive together. Any other kind of object runs its own
 * {@link IGeometry#intersect}, in the same leaf, so one box among a million spheres costs only
 * its own tests.
 */
final class LeafObjects {

    static final byte PACKED_SPHERE = 0;
    static final byte PACKED_TRIANGLE = 1;
    static final byte OWN_TEST = 2;
    private static final int SPHERE_SIZE = Sphere.NUMBERS;
    private static final int TRIANGLE_SIZE = Triangle.NUMBERS;

    final IGeometry[] objects;
    /** Each object's place in the scene file. */
    final int[] fileOrder;
    /** Each object's box, six floats: min x, y, z, max x, y, z. */
    final float[] boxes;
    /** Each object's kind, an index into {@link #kindNames}. */
    final byte[] kinds;
    /** Each object's way to test ({@link #PACKED_SPHERE}, ...), beside it for the hot loop. */
    private final byte[] testOf;
    /** The names of the kinds (a kind is a name and a way to test), for statistics. */
    final String[] kindNames;
    /**
     * Where each object's numbers start in {@link #numbers}; longer than the objects, with
     * zeros, if it is the builder's spare array.
     */
    final int[] offsets;
    /** The numbers of the packed tests, followed by zeros if it is the builder's spare array. */
    final float[] numbers;

    /**
     * Packs {@code objects} (in leaf order; {@code fileOrder} and {@code boxes} alike) with the
     * builder's threads, into the builder's spare arrays where they are long enough
     * ({@link BvhBuilder#spare}).
     */
    LeafObjects(IGeometry[] objects, int[] fileOrder, float[] boxes, BvhBuilder threads) {
        this.objects = objects;
        this.fileOrder = fileOrder;
        this.boxes = boxes;
        this.kinds = new byte[objects.length];
        this.offsets = reused(threads.spare().order(), objects.length);
        this.testOf = new byte[objects.length];
        List<String> names = new ArrayList<>();
        List<Byte> tests = new ArrayList<>();
        int size = 0;
        int kind = -1;
        for (int i = 0; i < objects.length; i++) { // in order: the offsets are a running sum
            byte test = testFor(objects[i]);
            String name = objects[i].kind();
            // a mesh's triangles come in a run of one kind: look the kind up only when it changes
            if (kind < 0 || test != tests.get(kind) || !name.equals(names.get(kind))) {
                kind = kindOf(names, tests, name, test);
                if (kind < 0) {
                    kind = names.size();
                    names.add(name);
                    tests.add(test);
                }
            }
            kinds[i] = (byte) kind;
            testOf[i] = test;
            offsets[i] = size;
            size += test == PACKED_SPHERE ? SPHERE_SIZE : test == PACKED_TRIANGLE ? TRIANGLE_SIZE : 0;
        }
        this.kindNames = names.toArray(String[]::new);
        this.numbers = reused(threads.spare().boxes(), size);
        if (threads.parallel()) {
            threads.forEach(this::pack);
        } else {
            for (int i = 0; i < objects.length; i++) {
                pack(i);
            }
        }
    }

    /**
     * {@code spare} if it has at least {@code length} places, else a new array of {@code length}.
     * The packing writes all of the first {@code length}; those after are zeroed, so that the
     * array depends on the tree alone.
     */
    private static int[] reused(int[] spare, int length) {
        if (spare.length < length) {
            return new int[length];
        }
        Arrays.fill(spare, length, spare.length, 0);
        return spare;
    }

    /** As {@link #reused(int[], int)}, for floats. */
    private static float[] reused(float[] spare, int length) {
        if (spare.length < length) {
            return new float[length];
        }
        Arrays.fill(spare, length, spare.length, 0);
        return spare;
    }

    /** The kind with this name and way to test among those found so far, or −1. */
    private static int kindOf(List<String> names, List<Byte> tests, String name, byte test) {
        for (int k = 0; k < names.size(); k++) {
            if (names.get(k).equals(name) && tests.get(k) == test) {
                return k;
            }
        }
        return -1;
    }

    private static byte testFor(IGeometry object) {
        return object instanceof Sphere ? PACKED_SPHERE : object instanceof Triangle ? PACKED_TRIANGLE : OWN_TEST;
    }

    private void pack(int i) {
        if (testOf[i] == PACKED_SPHERE) {
            ((Sphere) objects[i]).putTestNumbers(numbers, offsets[i]);
        } else if (testOf[i] == PACKED_TRIANGLE) {
            ((Triangle) objects[i]).putTestNumbers(numbers, offsets[i]);
        }
    }

    /**
     * Whether object {@code i} is a sphere of squared radius at least {@code leastSquared} that
     * no ray along D from an origin in the box from {@code lowest} to {@code highest} can hit
     * ({@link Sphere#everyRayMisses}); false for any other shape, and for a smaller sphere,
     * whose box leaves little room outside its outline.
     */
    boolean missedByEvery(int i, float leastSquared, float[] lowest, float[] highest, float dx, float dy, float dz) {
        int at = offsets[i];
        return testOf[i] == PACKED_SPHERE && numbers[at + 3] >= leastSquared
                && Sphere.everyRayMisses(numbers[at], numbers[at + 1], numbers[at + 2], numbers[at + 3], lowest,
                        highest, dx, dy, dz);
    }

    /**
     * The smallest {@code t ≥ 0} where the ray O + t·D hits object {@code i}, or NaN; {@code dd}
     * is D·D, the same for every object.
     */
    float t(int i, float ox, float oy, float oz, float dx, float dy, float dz, float dd) {
        byte test = testOf[i];
        if (test == PACKED_SPHERE) {
            return sphere(offsets[i], ox, oy, oz, dx, dy, dz, dd);
        }
        if (test == PACKED_TRIANGLE) {
            return Triangle.hit(numbers, offsets[i], ox, oy, oz, dx, dy, dz);
        }
        Intersection hit = objects[i].intersect(new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz)));
        return hit.t();
    }

    /** {@link Sphere#intersect} on packed numbers: equations 3.6 to 3.8. */
    private float sphere(int at, float ox, float oy, float oz, float dx, float dy, float dz, float dd) {
        float mx = ox - numbers[at];                                         // O − M
        float my = oy - numbers[at + 1];
        float mz = oz - numbers[at + 2];
        float a = dd;                                                        // equation 3.6
        float b = 2 * ((dx * mx) + (dy * my) + (dz * mz));                   // equation 3.7
        float c = ((mx * mx) + (my * my) + (mz * mz)) - numbers[at + 3];     // equation 3.8
        return Sphere.smallestRootNotBehind(a, b, b * b - 4 * a * c);
    }

    /**
     * The depth test's distance {@code |P − O|} of the hit at {@code t}, with P = O + t·D
     * rounded as {@link rtd.geometry.Intersection#at} rounds it.
     */
    static float distance(float t, float ox, float oy, float oz, float dx, float dy, float dz) {
        float x = (ox + dx * t) - ox;
        float y = (oy + dy * t) - oy;
        float z = (oz + dz * t) - oz;
        return (float) Math.sqrt(x * x + y * y + z * z);
    }
}
