package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.Box;
import rtd.geometry.TestObserver;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.geometry.TriangleNumbers;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The packed copies of the shapes' tests: the numbers each shape packs (or, for a triangle, its
 * own where they lie), where they go and which test reads them give the t of the shape's own
 * {@code intersect} to the last bit (each shape's own {@code intersect} calls the same static test); the box's slab test on numbers, on
 * cases worked out by hand (a face, an edge, a corner, a slab it lies in); and a shape without a
 * packed test is left to its own.
 */
@DisplayName("The packed tests")
class PackedTestsTest {

    private static final Color GREY = Color.fromRGB(0x808080);

    @Test
    void aBoxIsPackedAsItsSmallestCornerThenItsLargest() {
        Box box = Box.between(new Vector3f(4, -1, 2), new Vector3f(1, 5, -3), GREY, Material.DEFAULT);
        float[] numbers = new float[8];

        PackedTests.put(box, numbers, 1);

        assertThat(PackedTests.of(box)).isEqualTo(PackedTests.BOX);
        assertThat(PackedTests.size(PackedTests.BOX)).isEqualTo(6);
        assertThat(numbers).containsExactly(0, 1, -1, -3, 4, 5, 2, 0);
    }

    @Test
    void aRayAlongTheAxisThroughABoxEntersAtItsNearFaceAndFromInsideLeavesAtItsFarOne() {
        float[] box = {-1, -1, -1, 1, 1, 1};

        // from z = 5 towards −z: the face z = 1 at t = 4 (the x and y slabs are parallel: inside them)
        assertThat(Box.hit(box, 0, 0, 0, 5, 0, 0, -1, TestObserver.NONE)).isEqualTo(4f);
        // from the centre: it leaves through z = −1 at t = 1
        assertThat(Box.hit(box, 0, 0, 0, 0, 0, 0, -1, TestObserver.NONE)).isEqualTo(1f);
        // parallel to the x slabs and beside them: no hit
        assertThat(Box.hit(box, 0, 2, 0, 5, 0, 0, -1, TestObserver.NONE)).isNaN();
        // the box behind the ray: no hit
        assertThat(Box.hit(box, 0, 0, 0, 5, 0, 0, 1, TestObserver.NONE)).isNaN();
    }

    @Test
    void aRayFromABoxsFaceOrAlongItsFacesEdgesAndCornersHitsWhereTheSlabsSay() {
        float[] box = {-1, -1, -1, 1, 1, 1};

        // from the face z = 1 inwards: it enters at once, t = (1 − 1)/(−1) = −0, which counts as 0
        assertThat(Float.floatToIntBits(Box.hit(box, 0, 0, 0, 1, 0, 0, -1, TestObserver.NONE))).isEqualTo(Float.floatToIntBits(-0f));
        // in the plane of the face x = 1, parallel to it: inside that slab (its edge counts), through z = 1 at t = 4
        assertThat(Box.hit(box, 0, 1, 0, 5, 0, 0, -1, TestObserver.NONE)).isEqualTo(4f);
        assertThat(Box.hit(box, 0, -1, 0, 5, 0, 0, -1, TestObserver.NONE)).isEqualTo(4f);
        // towards the edge x = y = 1 from (2, 2, 0): both slabs entered at t = 1
        assertThat(Box.hit(box, 0, 2, 2, 0, -1, -1, 0, TestObserver.NONE)).isEqualTo(1f);
        // towards the corner (1, 1, 1) from (3, 3, 3): t = 2
        assertThat(Box.hit(box, 0, 3, 3, 3, -1, -1, -1, TestObserver.NONE)).isEqualTo(2f);
        // a direction of −0 along x is parallel to the x slabs, as +0 is
        assertThat(Box.hit(box, 0, 0, 0, 5, -0f, 0, -1, TestObserver.NONE)).isEqualTo(4f);
    }

    @Test
    void everyObjectOfALeafFindsItsShapesOwnTToTheLastBit() {
        Random random = new Random(7);
        Vector3f p1 = new Vector3f(-2, -1, 0.5f);
        Vector3f p2 = new Vector3f(2, -1.5f, 0);
        Vector3f p3 = new Vector3f(0.2f, 2, -0.5f);
        float[] mesh = new float[2 * Triangle.NUMBERS]; // the second triangle of a mesh's shared array
        TriangleNumbers.putNumbers(p3, p1, p2, mesh, Triangle.NUMBERS);
        List<IGeometry> shapes = List.of(
                new Sphere(new Vector3f(0.3f, -0.2f, 0.1f), 1.7f, GREY, Material.DEFAULT),
                new Triangle(p1, p2, p3, GREY, Material.DEFAULT),
                Box.between(new Vector3f(-1.5f, -0.5f, -2), new Vector3f(1, 1.25f, 0.75f), GREY, Material.DEFAULT),
                new Triangle(mesh, Triangle.NUMBERS, null, GREY, Material.DEFAULT),
                new Plane(new Vector3f(0, 0.5f, 0), new Vector3f(0.2f, 1, 0.1f), GREY, Material.DEFAULT));
        int[] fileOrder = {4, 1, 3, 0, 2};
        LeafObjects leaves = new LeafObjects(shapes, fileOrder, new int[0], new float[0], null, null);
        int hits = 0;
        for (int r = 0; r < 20_000; r++) {
            Ray ray = randomRay(random, r);
            Vector3f o = ray.origin();
            Vector3f d = ray.direction();
            for (int i = 0; i < fileOrder.length; i++) {
                IGeometry shape = shapes.get(fileOrder[i]);
                float inLeaf = leaves.t(i, o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), d.dot(d));
                float own = shape.intersect(ray).t();

                assertThat(Float.floatToIntBits(inLeaf)).as("%s, ray %s", shape.kind(), ray)
                        .isEqualTo(Float.floatToIntBits(own));
                hits += own >= 0 ? 1 : 0;
            }
        }
        assertThat(hits).as("rays that hit").isGreaterThan(40_000);
        // only the sphere's and the box's numbers are copied: the triangles' are read where they lie
        assertThat(leaves.numbers).hasSize(PackedTests.SPHERE_NUMBERS + Box.NUMBERS);
    }

    @Test
    void aShapeWithoutAPackedTestIsLeftToItsOwnIntersect() {
        Plane plane = new Plane(new Vector3f(0, 0, 0), new Vector3f(0, 1, 0), GREY, Material.DEFAULT);

        assertThat(PackedTests.of(plane)).isEqualTo(PackedTests.OWN_TEST);
        assertThat(PackedTests.size(PackedTests.OWN_TEST)).isZero();
    }

    /** From outside (towards the middle, more or less), from inside, and every fourth along an axis; random, so seldom grazing. */
    private static Ray randomRay(Random random, int i) {
        float spread = i % 3 == 0 ? 0.5f : 6;
        Vector3f origin = new Vector3f(spread * (random.nextFloat() * 2 - 1), spread * (random.nextFloat() * 2 - 1),
                spread * (random.nextFloat() * 2 - 1));
        Vector3f towards = new Vector3f(random.nextFloat() - 0.5f, random.nextFloat() - 0.5f, random.nextFloat() - 0.5f);
        Vector3f direction = towards.subtract(origin);
        if (i % 4 == 0) { // along one axis: the slabs of the other two are parallel to it
            int axis = i / 4 % 3;
            direction = new Vector3f(axis == 0 ? direction.x() : 0, axis == 1 ? direction.y() : 0,
                    axis == 2 ? direction.z() : 0);
        }
        return new Ray(origin, direction);
    }
}
