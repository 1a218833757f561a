package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The intersection test of a cone")
class ConeTest {

    /** Radius 1 at (0|0|0), 0 at (0|2|0), its apex: h = (0|1|0), k = −0.5, the radius 1 − s/2 at height s. */
    private final Cone cone = new Cone(Vector3f.ZERO, 1, new Vector3f(0, 2, 0), 0, Color.BLACK, Material.DEFAULT);

    private static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz) {
        return new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz));
    }

    /**
     * From (0|1|−5) along (0|0|1): t0 = 5 (O' = (0|1|0), the axis's middle), w = (0|1|0),
     * h·w = 1, h·R = 0, g = 1 − 0.5 = 0.5, so a = 1, b = 0, c = 1 − 1 − 0.25 = −0.25,
     * b² − 4ac = 1, t' = ∓0.5, t = 4.5 and 5.5: the side at radius 0.5.
     * The normal there: e = (0|0|−1), (e − k·h)/√1.25 = (0|0.5|−1)/√1.25.
     */
    @Test
    void aRayFromOutsideHitsTheSlantedSide() {
        Intersection hit = cone.intersect(ray(0, 1, -5, 0, 0, 1));
        assertThat(hit.t()).isEqualTo(4.5f);
        Vector3f n = cone.normalAt(hit.contactCoord());
        assertThat(n.x()).isEqualTo(0f);
        assertThat(n.y()).isCloseTo(0.4472136f, within(1e-6f));
        assertThat(n.z()).isCloseTo(-0.8944272f, within(1e-6f));
    }

    /**
     * Up from (0.5|−3|0): the first cap y = 0 at t = 3 (0.5 from its centre, inside radius 1); the
     * side's roots are 6 (s = 3, beyond the apex's end) and 4 (s = 1, where the ray leaves): t = 3.
     */
    @Test
    void aRayUpTheAxisHitsTheBase() {
        Intersection hit = cone.intersect(ray(0.5f, -3, 0, 0, 1, 0));
        assertThat(hit.t()).isEqualTo(3f);
        assertThat(cone.normalAt(hit.contactCoord())).isEqualTo(new Vector3f(0, -1, 0));
    }

    /** Down the axis from (0|5|0): the apex (0|2|0), a cap of radius 0, at t = 3; its normal along the axis. */
    @Test
    void aRayDownTheAxisHitsTheApex() {
        Intersection hit = cone.intersect(ray(0, 5, 0, 0, -1, 0));
        assertThat(hit.t()).isEqualTo(3f);
        assertThat(cone.normalAt(hit.contactCoord())).isEqualTo(new Vector3f(0, 1, 0));
        assertThat(cone.intersect(ray(0.01f, 5, 0, 0, -1, 0)).t()).as("beside the apex, the side lower down")
                .isCloseTo(3.02f, within(2e-4f)); // near an apex the roots lose digits
    }

    /** From (0|0.5|0) along x: the radius there is 0.75; t0 = 0, c = −0.5625, roots ∓0.75: the far side at t = 0.75. */
    @Test
    void aRayFromInsideHitsTheFarSide() {
        assertThat(cone.intersect(ray(0, 0.5f, 0, 1, 0, 0)).t()).isEqualTo(0.75f);
    }

    /** Beside the base, above the apex, and away. */
    @Test
    void aRayBesideOrBeyondTheApexMisses() {
        assertThat(cone.intersect(ray(1.5f, 0.5f, -5, 0, 0, 1)).happened()).as("beside").isFalse();
        assertThat(cone.intersect(ray(0, 2.5f, -5, 0, 0, 1)).happened()).as("above the apex: its mirror cone")
                .isFalse();
        assertThat(cone.intersect(ray(0, 1, -5, 0, 0, -1)).happened()).as("away").isFalse();
    }

    /** A truncated cone, radius 1 at y = 0 and 2 at y = 2: at y = 1 its radius is 1.5, t = 5 − 1.5 = 3.5. */
    @Test
    void aTruncatedConeWidensAlongItsAxis() {
        Cone truncated = new Cone(Vector3f.ZERO, 1, new Vector3f(0, 2, 0), 2, Color.BLACK, Material.DEFAULT);
        assertThat(truncated.intersect(ray(0, 1, -5, 0, 0, 1)).t()).isEqualTo(3.5f);
        assertThat(truncated.intersect(ray(1.8f, 5, 0, 0, -1, 0)).t()).as("the wide cap").isEqualTo(3f);
        assertThat(truncated.intersect(ray(1.8f, -5, 0, 0, 1, 0)).t()).as("up past the narrow cap, the side at y = 1.6")
                .isCloseTo(6.6f, within(1e-5f));
    }
}
