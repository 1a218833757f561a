package rtd.accel;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.scene.DepthTest;
import rtd.geometry.IGeometry;
import rtd.geometry.Triangle;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The objects of a {@link Bvh}'s leaves, in leaf order, so that the objects of a leaf lie next
 * to each other in memory: each one's place in the scene file (for the depth test's tie rule)
 * and, for spheres and boxes, the numbers of its intersection test packed into one array
 * ({@link PackedTests}). A triangle's numbers are read where they lie, in the triangle's own
 * array, which a mesh shares among thousands of its triangles: a second copy of a million
 * triangles' numbers would double the memory a mesh takes.
 *
 * <p>{@link #t} runs each shape's own kernel ({@code Sphere.hit}, {@code RayTriangle.hit},
 * {@code Box.hit}) on these numbers, so it finds the same {@code t} as the shape's
 * {@code intersect} to the last bit, without a wait for memory per reference followed: the
 * numbers of a leaf's objects arrive together. Any other kind of object runs its own
 * {@link IGeometry#intersect}, in the same leaf.
 */
final class LeafObjects {

    /** The scene's objects, in file order: for the objects tested by their own {@code intersect}. */
    private final List<IGeometry> scene;
    /** Each object's place in the scene file. */
    final int[] fileOrder;
    /** Each object's kind, an index into {@link #kindNames}. */
    final byte[] kinds;
    /** Each object's way to test ({@link PackedTests#SPHERE}, ...), beside it for the hot loop. */
    private final byte[] testOf;
    /** The names of the kinds (a kind is a name and a way to test), in the order the leaves meet them. */
    final String[] kindNames;
    /**
     * Where each object's numbers start in its array ({@link #arrays}); longer than the objects,
     * with zeros, if it is the builder's spare array.
     */
    private final int[] offsets;
    /** The array that holds each object's numbers: a triangle's own, or null for {@link #numbers}. */
    private final float[][] arrays;
    /** The numbers of the packed tests, followed by zeros if it is the builder's spare array. */
    final float[] numbers;

    /**
     * Packs the {@code scene}'s objects at places {@code fileOrder} (in leaf order), into
     * {@code spareInts} and {@code spareFloats} where they are long enough (the builder's arrays,
     * which the tree no longer needs), on {@code pool} or on this thread if it is null; writes each
     * one's {@link KnownShapes#rounding} to {@code roundings}, unless it is null, in leaf order too,
     * linear at {@code [2i]} and quadratic at {@code [2i + 1]}, for the {@link Bvh} to grow its
     * nodes by. Each object is read in file order, as it lies in memory, and its numbers are
     * written to its place in leaf order.
     */
    LeafObjects(List<IGeometry> scene, int[] fileOrder, int[] spareInts, float[] spareFloats, ForkJoinPool pool,
            float[] roundings) {
        this.scene = scene;
        this.fileOrder = fileOrder;
        int count = fileOrder.length;
        List<String> names = new ArrayList<>();
        List<Byte> tests = new ArrayList<>();
        byte[] fileKinds = kindsInFileOrder(scene, names, tests);
        byte[] testOfKind = new byte[tests.size()];
        for (int k = 0; k < testOfKind.length; k++) {
            testOfKind[k] = tests.get(k);
        }
        // the kinds are numbered anew as the leaves meet them, so that the statistics list them in that order
        byte[] leafKind = new byte[names.size()];
        Arrays.fill(leafKind, (byte) -1);
        List<String> leafNames = new ArrayList<>();
        this.kinds = new byte[count];
        this.testOf = new byte[count];
        this.offsets = reused(spareInts, count);
        this.arrays = new float[count][];
        int[] leafPlaces = new int[scene.size()]; // per place in the file, the place in leaf order, or −1 for none
        Arrays.fill(leafPlaces, -1);
        int size = 0;
        for (int i = 0; i < count; i++) { // in order: the offsets are a running sum
            int f = fileOrder[i];
            leafPlaces[f] = i;
            int kind = fileKinds[f];
            if (leafKind[kind] < 0) {
                leafKind[kind] = (byte) leafNames.size();
                leafNames.add(names.get(kind));
            }
            byte test = testOfKind[kind];
            kinds[i] = leafKind[kind];
            testOf[i] = test;
            offsets[i] = size;
            size += PackedTests.size(test);
        }
        this.kindNames = leafNames.toArray(String[]::new);
        this.numbers = reused(spareFloats, size);
        new Parts(scene.size(), pool).run((start, end, part) -> {
            for (int f = start; f < end; f++) {
                pack(f, leafPlaces[f], roundings);
            }
        });
    }

    /**
     * Each object's kind, by place in the file, as an index into {@code names} and {@code tests},
     * which it fills in the order the file meets the kinds.
     */
    private static byte[] kindsInFileOrder(List<IGeometry> scene, List<String> names, List<Byte> tests) {
        byte[] fileKinds = new byte[scene.size()];
        int kind = -1;
        for (int f = 0; f < fileKinds.length; f++) {
            IGeometry object = scene.get(f);
            byte test = PackedTests.of(object);
            String name = object.kind();
            // a mesh's triangles come in a run of one kind: look the kind up only when it changes
            if (kind < 0 || test != tests.get(kind) || !name.equals(names.get(kind))) {
                kind = kindOf(names, tests, name, test);
                if (kind < 0) {
                    kind = names.size();
                    names.add(name);
                    tests.add(test);
                }
            }
            fileKinds[f] = (byte) kind;
        }
        return fileKinds;
    }

    /**
     * {@code spare} if it has at least {@code length} places and at most twice as many, else a
     * new array of {@code length}: a spare that would hold few numbers is left to the collector.
     * The packing writes all of the first {@code length}; those after are zeroed, so that the
     * array depends on the tree alone.
     */
    private static int[] reused(int[] spare, int length) {
        if (spare.length < length || spare.length > 2 * length) {
            return new int[length];
        }
        Arrays.fill(spare, length, spare.length, 0);
        return spare;
    }

    /** As {@link #reused(int[], int)}, for floats. */
    private static float[] reused(float[] spare, int length) {
        if (spare.length < length || spare.length > 2 * length) {
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

    /**
     * Packs the numbers and the rounding of the object at place {@code f} in the file, which has
     * place {@code i} in leaf order (or none, −1).
     */
    private void pack(int f, int i, float[] roundings) {
        if (i < 0) {
            return;
        }
        IGeometry object = scene.get(f);
        if (roundings != null) {
            Rounding rounding = KnownShapes.rounding(object);
            roundings[2 * i] = rounding.linear();
            roundings[2 * i + 1] = rounding.quadratic();
        }
        if (object instanceof Triangle triangle) {
            arrays[i] = triangle.numbers();
            offsets[i] = triangle.numbersAt();
        } else { // no reference to numbers stored: a million stores into an old array keep the collector busy
            PackedTests.put(object, numbers, offsets[i]);
        }
    }

    /** Where the numbers of object {@code i}'s test start in {@link #numbers}, or −1 if it is no sphere. */
    int sphereAt(int i) {
        return testOf[i] == PackedTests.SPHERE ? offsets[i] : -1;
    }

    /**
     * The smallest {@code t ≥ 0} where the ray O + t·D hits object {@code i}, or NaN; {@code dd}
     * is D·D, the same for every object.
     */
    float t(int i, float ox, float oy, float oz, float dx, float dy, float dz, float dd) {
        byte test = testOf[i];
        if (test != PackedTests.OWN_TEST) {
            float[] array = arrays[i];
            return PackedTests.t(test, array != null ? array : numbers, offsets[i], ox, oy, oz, dx, dy, dz, dd);
        }
        Ray ray = new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz));
        return scene.get(fileOrder[i]).intersect(ray).t();
    }

    /**
     * The depth test's distance {@code |P − O|} of the hit at {@code t}, with P = O + t·D
     * rounded as {@link rtd.geometry.Intersection#at} rounds it.
     */
    static float distance(float t, float ox, float oy, float oz, float dx, float dy, float dz) {
        return DepthTest.distance(ox + dx * t, oy + dy * t, oz + dz * t, ox, oy, oz);
    }
}
