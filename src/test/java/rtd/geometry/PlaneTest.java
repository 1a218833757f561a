package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The intersection test of a plane")
class PlaneTest {

    /** The floor y = −1, its normal given three times too long. */
    private final Plane floor = new Plane(new Vector3f(5, -1, 7), new Vector3f(0, 3, 0), Color.BLACK, Material.DEFAULT);

    private static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz) {
        return new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz));
    }

    @Test
    void aRayStraightDownHitsAtItsHeightAboveThePlane() {
        Intersection hit = floor.intersect(ray(2, 4, 3, 0, -1, 0));
        assertThat(hit.t()).isEqualTo(5f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(2, -1, 3));
    }

    @Test
    void anObliqueRayHitsWhereItsHeightRunsOut() {
        // From (0, 1, 0) along (1, -0.5, 0): height 2 above the floor, lost at 0.5 per unit of t.
        assertThat(floor.intersect(ray(0, 1, 0, 1, -0.5f, 0)).t()).isEqualTo(4f);
    }

    @Test
    void aRayParallelToThePlaneNeverHitsIt() {
        assertThat(floor.intersect(ray(0, 1, 0, 1, 0, 1)).happened()).isFalse();
        assertThat(floor.intersect(ray(0, -1, 0, 1, 0, 0)).happened()).as("a ray in the plane").isFalse();
    }

    @Test
    void aPlaneBehindTheRayIsNotHit() {
        assertThat(floor.intersect(ray(0, 1, 0, 0, 1, 0)).happened()).isFalse();
    }

    @Test
    void aRayFromBelowHitsItToo() {
        assertThat(floor.intersect(ray(0, -3, 0, 0, 1, 0)).t()).isEqualTo(2f);
    }

    @Test
    void itsNormalIsTheGivenNormalOfLengthOneEverywhereAndItHasNoBox() {
        assertThat(floor.normalAt(new Vector3f(100, -1, -50))).isEqualTo(new Vector3f(0, 1, 0));
        assertThat(floor.bounds().isBounded()).isFalse();
    }

    @Test
    void aRaySoNearlyParallelThatItsHitLiesBeyondFloatsRangeMisses() {
        Intersection hit = floor.intersect(ray(0, 1, 0, 1, -1e-45f, 0));
        assertThat(hit.happened()).isFalse();
        assertThat(hit.contactCoord().isFinite()).isFalse();
    }
}
