package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

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
}
