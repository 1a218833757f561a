package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.image.Color;

@DisplayName("The intersection test of a sphere (section 3.2.2)")
class SphereTest {

    private final Sphere sphere = new Sphere(new Vector3f(0, 0, 0), 2, Color.BLACK);

    private static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz) {
        return new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz));
    }

    @Test
    void aRayThroughTheCentreHitsTheNearSurfaceAtTheRightT() {
        Intersection hit = sphere.intersect(ray(0, 0, 10, 0, 0, -1));
        assertThat(hit.happened()).isTrue();
        assertThat(hit.t()).isEqualTo(8f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(0, 0, 2));
    }

    @Test
    void aLongerDirectionGivesASmallerTButTheSamePoint() {
        Intersection hit = sphere.intersect(ray(0, 0, 10, 0, 0, -4));
        assertThat(hit.t()).isEqualTo(2f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(0, 0, 2));
    }

    @Test
    void aRayThatPassesBesideTheSphereMisses() {
        assertThat(sphere.intersect(ray(2.5f, 0, 10, 0, 0, -1)).happened()).isFalse();
    }

    @Test
    void aRayThatGrazesTheSphereTouchesItInOnePoint() {
        Intersection hit = sphere.intersect(ray(2, 0, 10, 0, 0, -1));
        assertThat(hit.happened()).isTrue();
        assertThat(hit.t()).isEqualTo(10f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(2, 0, 0));
    }

    @Test
    void aRayThatStartsInsideHitsTheFarSurface() {
        Intersection hit = sphere.intersect(ray(0, 0, 0, 0, 0, -1));
        assertThat(hit.happened()).isTrue();
        assertThat(hit.t()).isEqualTo(2f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(0, 0, -2));
    }

    @Test
    void aSphereBehindTheRaysOriginIsNotHit() {
        assertThat(sphere.intersect(ray(0, 0, -10, 0, 0, -1)).happened()).isFalse();
    }

    @Test
    void theBoundsHoldTheSphereAndAreOnlySlightlyWider() {
        BoundingBox box = sphere.bounds();
        assertThat(box.min().x()).isLessThan(-2f).isGreaterThan(-2.1f);
        assertThat(box.max().z()).isGreaterThan(2f).isLessThan(2.1f);
    }
}
