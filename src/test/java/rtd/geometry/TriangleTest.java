package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The intersection test of a triangle")
class TriangleTest {

    /** The triangle (0,0,0), (4,0,0), (0,4,0) in the plane z = 0, facing +z. */
    private final Triangle triangle = new Triangle(new Vector3f(0, 0, 0), new Vector3f(4, 0, 0), new Vector3f(0, 4, 0),
            Color.BLACK, Material.DEFAULT);

    private static Ray down(float x, float y) {
        return new Ray(new Vector3f(x, y, 10), new Vector3f(0, 0, -2));
    }

    @Test
    void aRayThroughTheInsideHitsAtTheRightT() {
        Intersection hit = triangle.intersect(down(1, 1));
        assertThat(hit.t()).isEqualTo(5f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(1, 1, 0));
    }

    @Test
    void aRayThroughAnEdgeOrACornerHits() {
        assertThat(triangle.intersect(down(2, 0)).happened()).as("the edge on the x axis").isTrue();
        assertThat(triangle.intersect(down(2, 2)).happened()).as("the long edge").isTrue();
        assertThat(triangle.intersect(down(0, 4)).happened()).as("a corner").isTrue();
        assertThat(triangle.intersect(down(0, 0)).happened()).as("the corner at the origin").isTrue();
    }

    @Test
    void aRayJustOutsideAnEdgeMisses() {
        assertThat(triangle.intersect(down(2.01f, 2)).happened()).isFalse();
        assertThat(triangle.intersect(down(-0.01f, 1)).happened()).isFalse();
        assertThat(triangle.intersect(down(1, -0.01f)).happened()).isFalse();
    }

    @Test
    void aRayInTheTrianglesPlaneOrBehindItMisses() {
        assertThat(triangle.intersect(new Ray(new Vector3f(-1, 1, 0), new Vector3f(1, 0, 0))).happened()).isFalse();
        assertThat(triangle.intersect(new Ray(new Vector3f(1, 1, -1), new Vector3f(0, 0, -1))).happened()).isFalse();
    }

    @Test
    void aTriangleOfZeroAreaIsNeverHit() {
        Triangle flat = new Triangle(new Vector3f(0, 0, 0), new Vector3f(1, 1, 0), new Vector3f(2, 2, 0), Color.BLACK,
                Material.DEFAULT);
        assertThat(flat.intersect(down(1, 1)).happened()).isFalse();
        assertThat(flat.intersect(new Ray(new Vector3f(1, 1, 5), new Vector3f(0.1f, 0, -1))).happened()).isFalse();
    }

    @Test
    void itsNormalIsTheUnitCrossProductOfItsEdges() {
        assertThat(triangle.normalAt(new Vector3f(1, 1, 0))).isEqualTo(new Vector3f(0, 0, 1));
        Triangle reversed = new Triangle(new Vector3f(0, 0, 0), new Vector3f(0, 4, 0), new Vector3f(4, 0, 0),
                Color.BLACK, Material.DEFAULT);
        assertThat(reversed.normalAt(new Vector3f(1, 1, 0))).isEqualTo(new Vector3f(0, 0, -1));
    }

    @Test
    void aSmoothTriangleBlendsItsCornersNormalsAsGivenByBarycentricWeightsThenNormalises() {
        Vector3f[] normals = {new Vector3f(0, 0, 1), new Vector3f(2, 0, 0), new Vector3f(0, 3, 0)}; // any length
        Triangle smooth = new Triangle(new Vector3f(0, 0, 0), new Vector3f(4, 0, 0), new Vector3f(0, 4, 0), normals,
                Color.BLACK, Material.DEFAULT);
        Vector3f atFirst = smooth.normalAt(new Vector3f(0, 0, 0));
        assertThat(atFirst).isEqualTo(new Vector3f(0, 0, 1));
        Vector3f atSecond = smooth.normalAt(new Vector3f(4, 0, 0));
        assertThat(atSecond).isEqualTo(new Vector3f(1, 0, 0));
        // The middle of the edge from p2 to p3: half of (2,0,0) and half of (0,3,0), normalised: (2,3,0)/√13.
        Vector3f between = smooth.normalAt(new Vector3f(2, 2, 0));
        assertThat(between.x()).isCloseTo((float) (2 / Math.sqrt(13)), within(1e-6f));
        assertThat(between.y()).isCloseTo((float) (3 / Math.sqrt(13)), within(1e-6f));
        assertThat(between.z()).isCloseTo(0f, within(1e-6f));
    }

    @Test
    void raysThroughTheEdgeTwoWellShapedTrianglesShareNeverSlipBetweenThem() {
        java.util.Random random = new java.util.Random(5);
        for (int r = 0; r < 20_000; r++) {
            // Two triangles of a mesh that share the edge a-b, at some place, size and tilt.
            Vector3f shift = new Vector3f(random.nextFloat() * 200 - 100, random.nextFloat() * 200 - 100, random.nextFloat() * 200 - 100);
            float size = (float) Math.pow(10, random.nextInt(4) - 2);
            Vector3f a = shift.add(new Vector3f(random.nextFloat(), random.nextFloat(), random.nextFloat()).multiply(size));
            Vector3f b = shift.add(new Vector3f(random.nextFloat(), random.nextFloat(), random.nextFloat()).multiply(size));
            // c off the edge's middle, so that the triangles are not needles (their edges may crack)
            Vector3f across = b.subtract(a).cross(new Vector3f(random.nextFloat() - 0.5f, random.nextFloat() - 0.5f, 1))
                    .normalize().multiply(b.subtract(a).magnitude() * (0.2f + random.nextFloat()));
            Vector3f c = a.add(b).multiply(0.5f).add(across);
            Vector3f d = a.add(b).subtract(c); // across the edge from c
            Triangle first = new Triangle(a, b, c, Color.BLACK, Material.DEFAULT);
            Triangle second = new Triangle(b, a, d, Color.BLACK, Material.DEFAULT);
            // A ray through a point of the edge, from up to a hundred sizes away, at most 45° from the normal
            // (a flatter ray that passes a rounding error beside the edge may miss both faces of a fold for real).
            Vector3f onEdge = a.add(b.subtract(a).multiply(random.nextFloat()));
            Vector3f normal = first.planeNormal().normalize();
            float away = size * (1 + random.nextFloat() * 100);
            Vector3f from = onEdge.add(normal.multiply(away))
                    .add(new Vector3f(random.nextFloat() - 0.5f, random.nextFloat() - 0.5f, random.nextFloat() - 0.5f)
                            .multiply(away));
            Ray ray = new Ray(from, onEdge.subtract(from));
            assertThat(first.intersect(ray).happened() || second.intersect(ray).happened())
                    .as("ray %d %s between %s and %s", r, ray, first.corner(2), d).isTrue();
        }
    }

    /** A triangle of any size from 1e-4 to 1e4, now and then a needle. */
    private static Triangle randomTriangle(Random random) {
        float scale = (float) Math.pow(10, random.nextInt(9) - 4);
        Vector3f p1 = new Vector3f((random.nextFloat() - 0.5f) * scale, (random.nextFloat() - 0.5f) * scale, -random.nextFloat() * scale);
        Vector3f p2 = p1.add(new Vector3f(random.nextFloat() * scale, random.nextFloat() * scale, 0));
        Vector3f p3 = random.nextInt(4) == 0 // a needle now and then
                ? p1.add(p2.subtract(p1).multiply(2 + random.nextFloat() * 1e-6f))
                : p1.add(new Vector3f(0, random.nextFloat() * scale, random.nextFloat() * scale));
        return new Triangle(p1, p2, p3, Color.BLACK, Material.DEFAULT);
    }

    @Test
    void itsBoxHoldsItsCornersGrownByAFewRoundingErrorsOfItsSize() {
        // |p2 − p1| = |p3 − p1| = 4, |p3 − p2| = 4√2, |n| = 16: thinness 4·4√2/16 = √2; the edges summed over the
        // axes 16, the largest coordinate 4. Grown by u·(32·8·√2 + 2·16u√2·16/u + 64·(4 + 8)) and 8u·4: 1.12421e-4
        BoundingBox box = triangle.bounds();

        float grow = 1.12421e-4f;
        assertThat(new float[] {box.min().x(), box.min().y(), box.min().z(), box.max().z()})
                .containsExactly(new float[] {-grow, -grow, -grow, grow}, within(1e-9f));
        assertThat(new float[] {box.max().x(), box.max().y()}).containsExactly(new float[] {4 + grow, 4 + grow}, within(1e-6f));
    }

    @Test
    void writesItsBoxWhereItIsToldAndNothingElse() {
        Random random = new Random(17);
        for (int i = 0; i < 1_000; i++) {
            Triangle any = randomTriangle(random);
            float[] written = new float[10];
            java.util.Arrays.fill(written, -7f);
            any.putBounds(written, 3);
            float[] expected = {-7f, -7f, -7f, 0, 0, 0, 0, 0, 0, -7f};
            any.bounds().put(expected, 3);
            assertThat(written).isEqualTo(expected);
        }
    }

    @Test
    void itsTestFindsTheSameTToTheLastBitWhereAMeshSharesOneArray() {
        Random random = new Random(13);
        float[] shared = new float[3 * Triangle.NUMBERS];
        int hits = 0;
        for (int i = 0; i < 10_000; i++) {
            Triangle any = randomTriangle(random);
            int at = Triangle.NUMBERS * random.nextInt(3);
            System.arraycopy(any.numbers(), any.numbersAt(), shared, at, Triangle.NUMBERS);
            Triangle inMesh = new Triangle(shared, at, null, Color.BLACK, Material.DEFAULT);
            Vector3f origin = new Vector3f(random.nextFloat() * 20 - 10, random.nextFloat() * 20 - 10, 10);
            Vector3f towards = any.corner(random.nextInt(3)).add(any.corner(random.nextInt(3))).multiply(0.5f);
            Ray ray = new Ray(origin, towards.subtract(origin));
            float t = inMesh.intersect(ray).t();
            Intersection expected = any.intersect(ray);
            assertThat(Float.floatToRawIntBits(t)).as(ray + " on " + any.corner(0) + " " + any.corner(1) + " "
                    + any.corner(2)).isEqualTo(Float.floatToRawIntBits(expected.t()));
            hits += expected.happened() ? 1 : 0;
        }
        assertThat(hits).as("rays that hit").isGreaterThan(5_000);
    }
}
