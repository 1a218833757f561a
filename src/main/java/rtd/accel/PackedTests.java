package rtd.accel;

import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.RayTriangle;
import rtd.geometry.Sphere;
import rtd.geometry.TestObserver;
import rtd.geometry.Triangle;

/**
 * The shapes whose intersection test the accelerators run on their numbers, instead of through
 * each object's own {@link IGeometry#intersect}: spheres and boxes on a copy packed side by side
 * in one array ({@link LeafObjects}), triangles on their own numbers where they lie. Each packed test calls the shape's
 * own kernel ({@link Sphere#hit}, {@link RayTriangle#hit}, {@link Box#hit}), which its
 * {@code intersect} calls too, so it finds the same t to the last bit and shows any edit of the
 * kernel; it only skips following references, and makes no {@code Ray} or {@code Intersection}
 * on the way. Not in the paper.
 *
 * <p>Any other shape is tested by its own {@code intersect} ({@link #OWN_TEST}); a new shape
 * works without a line here, and gets a packed test here when it is worth one.
 */
final class PackedTests {

    static final byte SPHERE = 0;
    static final byte TRIANGLE = 1;
    static final byte BOX = 2;
    /** A shape without a packed test: its own {@code intersect} runs. */
    static final byte OWN_TEST = 3;
    /** A sphere's numbers: its centre M's x, y, z and its radius r. */
    static final int SPHERE_NUMBERS = 4;

    private PackedTests() {
    }

    /** How {@code object} is tested. */
    static byte of(IGeometry object) {
        return object instanceof Sphere ? SPHERE : object instanceof Triangle ? TRIANGLE
                : object instanceof Box ? BOX : OWN_TEST;
    }

    /**
     * How many numbers {@link #put} packs for the test {@code test}; none for a triangle, whose
     * own numbers are read ({@link Triangle#numbers}), or for {@link #OWN_TEST}.
     */
    static int size(byte test) {
        return test == SPHERE ? SPHERE_NUMBERS : test == BOX ? Box.NUMBERS : 0;
    }

    /** Writes the numbers of a sphere's or a box's test into {@code numbers} from {@code at}; nothing for another. */
    static void put(IGeometry object, float[] numbers, int at) {
        if (object instanceof Sphere sphere) {
            numbers[at] = sphere.center().x();
            numbers[at + 1] = sphere.center().y();
            numbers[at + 2] = sphere.center().z();
            numbers[at + 3] = sphere.radius();
        } else if (object instanceof Box box) {
            box.putTestNumbers(numbers, at);
        }
    }

    /**
     * The smallest {@code t ≥ 0} where the ray O + t·D hits the object whose numbers lie at
     * {@code numbers[at]}, by the packed test {@code test} (not {@link #OWN_TEST}), or NaN;
     * {@code dd} is D·D.
     */
    static float t(byte test, float[] numbers, int at, float ox, float oy, float oz, float dx, float dy, float dz,
            float dd) {
        if (test == SPHERE) {
            return sphere(numbers, at, ox, oy, oz, dx, dy, dz);
        }
        if (test == TRIANGLE) {
            return RayTriangle.hit(numbers, at, ox, oy, oz, dx, dy, dz, TestObserver.NONE);
        }
        return Box.hit(numbers, at, ox, oy, oz, dx, dy, dz, TestObserver.NONE);
    }

    /** {@link Sphere#hit} on the numbers {@link #put} wrote at {@code at}: M, then r. */
    private static float sphere(float[] numbers, int at, float ox, float oy, float oz, float dx, float dy, float dz) {
        return Sphere.hit(numbers[at], numbers[at + 1], numbers[at + 2], numbers[at + 3], ox, oy, oz, dx, dy, dz,
                TestObserver.NONE);
    }
}
