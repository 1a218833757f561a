package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The intersection test of a cylinder")
class CylinderTest {

    /** The cylinder of radius 1 from (0|0|0) up to (0|2|0): h = (0|1|0), its length 2. */
    private final Cylinder cylinder = new Cylinder(Vector3f.ZERO, new Vector3f(0, 2, 0), 1, Color.BLACK,
            Material.DEFAULT);

    private static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz) {
        return new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz));
    }

    /**
     * From (0|1|−5) along (0|0|1): the axis's middle M = (0|1|0), t0 = (M − O)·R/(R·R) = 5, so
     * O' = (0|1|0) and w = O' − A = (0|1|0); h·R = 0, h·w = 1: a = 1, b = 0, c = 1 − 1 − 1 = −1,
     * b² − 4ac = 4, t' = ∓1, t = 5 ∓ 1 = 4 and 6, both at s = 1: t = 4.
     */
    @Test
    void aRayFromOutsideHitsTheSide() {
        Intersection hit = cylinder.intersect(ray(0, 1, -5, 0, 0, 1));
        assertThat(hit.t()).isEqualTo(4f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(0, 1, -1));
        assertThat(cylinder.normalAt(hit.contactCoord())).isEqualTo(new Vector3f(0, 0, -1));
    }

    /** From (0.5|5|0) straight down: a = 1 − 1 = 0 and b = 0, no side; the top cap's plane y = 2 at t = 3. */
    @Test
    void aRayAlongTheAxisHitsTheCap() {
        Intersection hit = cylinder.intersect(ray(0.5f, 5, 0, 0, -1, 0));
        assertThat(hit.t()).isEqualTo(3f);
        assertThat(cylinder.normalAt(hit.contactCoord())).isEqualTo(new Vector3f(0, 1, 0));
        assertThat(cylinder.intersect(ray(0.5f, -4, 0, 0, 1, 0)).t()).as("from below, the first cap").isEqualTo(4f);
        assertThat(cylinder.normalAt(new Vector3f(0.5f, 0, 0))).isEqualTo(new Vector3f(0, -1, 0));
    }

    /** From the centre (0|1|0) along x: t0 = 0, c = 1 − 1 − 1 = −1, roots ∓1: the far side at t = 1; up: the top cap at t = 1. */
    @Test
    void aRayFromInsideHitsTheFarSide() {
        assertThat(cylinder.intersect(ray(0, 1, 0, 1, 0, 0)).t()).isEqualTo(1f);
        assertThat(cylinder.normalAt(new Vector3f(1, 1, 0))).isEqualTo(new Vector3f(1, 0, 0));
        assertThat(cylinder.intersect(ray(0, 1, 0, 0, 1, 0)).t()).as("along the axis, the cap").isEqualTo(1f);
    }

    /** Beside it (t0 = 5, w = (2|1|0), c = 5 − 1 − 1 = 3, b² − 4ac = −12 < 0), above it (roots at s = 3 > 2, parallel to the caps), and away. */
    @Test
    void aRayBesideAboveOrAwayMisses() {
        assertThat(cylinder.intersect(ray(2, 1, -5, 0, 0, 1)).happened()).as("beside").isFalse();
        assertThat(cylinder.intersect(ray(0, 3, -5, 0, 0, 1)).happened()).as("above").isFalse();
        assertThat(cylinder.intersect(ray(0, 1, -5, 0, 0, -1)).happened()).as("away").isFalse();
        assertThat(cylinder.intersect(ray(1.5f, 5, 0, 0, -1, 0)).happened()).as("along the axis, beside").isFalse();
    }

    /** The axis from (0|0|0) to (2|2|0): a ray down from (1|1|5) meets the side at z = 1, t = 4, normal (0|0|1). */
    @Test
    void aTiltedCylinderIsHitWhereItsSideIs() {
        Cylinder tilted = new Cylinder(Vector3f.ZERO, new Vector3f(2, 2, 0), 1, Color.BLACK, Material.DEFAULT);
        Intersection hit = tilted.intersect(ray(1, 1, 5, 0, 0, -1));
        assertThat(hit.t()).isCloseTo(4f, within(1e-5f));
        Vector3f n = tilted.normalAt(hit.contactCoord());
        assertThat(n.z()).isCloseTo(1f, within(1e-5f));
        float cap = tilted.intersect(ray(-5, -5, 0, 1, 1, 0)).t(); // along the axis: the first cap at (0|0|0), t = 5
        assertThat(cap).isCloseTo(5f, within(1e-5f));
    }

    /** Its box holds the whole solid: the end points grown by the radius. */
    @Test
    void itsBoxHoldsTheCaps() {
        BoundingBox box = cylinder.bounds();
        assertThat(box.min().x()).isLessThanOrEqualTo(-1);
        assertThat(box.max().y()).isGreaterThanOrEqualTo(2);
        assertThat(box.max().z()).isGreaterThanOrEqualTo(1).isLessThan(1.1f);
    }
}
