package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The intersection test of a box (the slab test)")
class BoxTest {

    /** The box from (−1,−2,−3) to (1,2,3), its corners given in the other order. */
    private final Box box = Box.between(new Vector3f(1, 2, 3), new Vector3f(-1, -2, -3), Color.BLACK, Material.DEFAULT);

    private static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz) {
        return new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz));
    }

    @Test
    void itsCornersAreSortedWhateverOrderTheyComeIn() {
        assertThat(box.min()).isEqualTo(new Vector3f(-1, -2, -3));
        assertThat(box.max()).isEqualTo(new Vector3f(1, 2, 3));
    }

    @Test
    void aRayFromOutsideHitsTheNearFace() {
        Intersection hit = box.intersect(ray(0, 0, 10, 0, 0, -1));
        assertThat(hit.t()).isEqualTo(7f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(0, 0, 3));
        assertThat(box.intersect(ray(5, 0.5f, 0, -1, 0, 0)).t()).isEqualTo(4f);
    }

    @Test
    void aRayThatStartsInsideHitsTheFarSide() {
        Intersection hit = box.intersect(ray(0, 0, 0, 0, 1, 0));
        assertThat(hit.t()).isEqualTo(2f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(0, 2, 0));
    }

    @Test
    void aRayThatPassesBesideOrRunsParallelOutsideMisses() {
        assertThat(box.intersect(ray(1.5f, 0, 10, 0, 0, -1)).happened()).isFalse();
        assertThat(box.intersect(ray(0, 3, 0, 1, 0, 0)).happened()).as("parallel, above it").isFalse();
        assertThat(box.intersect(ray(0, 0, 10, 0, 0, 1)).happened()).as("away from it").isFalse();
    }

    @Test
    void aRayThroughAnEdgeHits() {
        assertThat(box.intersect(ray(1, 2, 10, 0, 0, -1)).t()).isEqualTo(7f);
    }

    @Test
    void itsNormalIsTheNormalOfTheFaceHit() {
        assertThat(box.normalAt(new Vector3f(0, 0, 3))).isEqualTo(new Vector3f(0, 0, 1));
        assertThat(box.normalAt(new Vector3f(-1, 0.5f, 1))).isEqualTo(new Vector3f(-1, 0, 0));
        assertThat(box.normalAt(new Vector3f(0.2f, -2, -2.5f))).isEqualTo(new Vector3f(0, -1, 0));
    }

    @Test
    void aRayOfNoLengthFromInsideHitsNothing() {
        assertThat(box.intersect(ray(0, 0, 0, 0, 0, 0)).happened()).isFalse();
    }

    /**
     * A ray along the plane of the left face (x = −1) hits the front face (z = 3) on their shared
     * edge, at (−1|0|3): it is as near the left face as the front one, but runs along it and
     * crosses only the front. Its normal is the front's, (0|0|1), not the left's (−1|0|0), which
     * would turn the lit face dark in a one-pixel seam.
     */
    @Test
    void aHitOnAnEdgeBelongsToTheFaceTheRayCrossesNotTheOneItRunsAlong() {
        Ray alongTheLeftFace = ray(-1, 0, 10, 0, 0, -1);
        Vector3f point = box.intersect(alongTheLeftFace).contactCoord();
        assertThat(point).isEqualTo(new Vector3f(-1, 0, 3));
        assertThat(box.normalAt(point, alongTheLeftFace.direction())).isEqualTo(new Vector3f(0, 0, 1));
        Ray alongTheTopFace = ray(0, 2, -10, 0, 0, 1); // y = 2, entering the back face z = −3
        assertThat(box.normalAt(box.intersect(alongTheTopFace).contactCoord(), alongTheTopFace.direction()))
                .isEqualTo(new Vector3f(0, 0, -1));
        Ray fromInside = ray(1, 0, 0, 0, 0, 1); // inside, on the right face's plane: it leaves through the front
        assertThat(box.normalAt(box.intersect(fromInside).contactCoord(), fromInside.direction()))
                .isEqualTo(new Vector3f(0, 0, 1));
    }

    @Test
    void aHitInsideAFaceTakesThatFacesNormalFromAnyDirection() {
        Vector3f onTheRightFace = new Vector3f(1, 0.5f, -1);
        assertThat(box.normalAt(onTheRightFace)).isEqualTo(new Vector3f(1, 0, 0));
        assertThat(box.normalAt(onTheRightFace, new Vector3f(-1, 0.3f, 0.2f))).isEqualTo(new Vector3f(1, 0, 0));
        assertThat(box.normalAt(onTheRightFace, new Vector3f(-0.01f, -1, 0))).isEqualTo(new Vector3f(1, 0, 0));
    }
}
