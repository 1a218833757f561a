package rtd.camera;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The orthographic camera (Listing 4.1)")
class OrthographicCameraTest {

    private static void assertVector(Vector3f actual, double x, double y, double z) {
        assertThat(actual.x()).isCloseTo((float) x, within(1e-6f));
        assertThat(actual.y()).isCloseTo((float) y, within(1e-6f));
        assertThat(actual.z()).isCloseTo((float) z, within(1e-6f));
    }

    @Test
    void lookingAlongMinusZWorldXPointsRightAndWorldYUp() {
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50);
        assertVector(camera.widthVector(), 1, 0, 0);
        assertVector(camera.heightVector(), 0, -1, 0);
    }

    @Test
    void anObliqueViewGetsPerpendicularUnitAxes() {
        OrthographicCamera camera = new OrthographicCamera(Vector3f.ZERO, new Vector3f(-1, -1, -1), 10);
        double r2 = Math.sqrt(2);
        double r6 = Math.sqrt(6);
        assertVector(camera.widthVector(), 1 / r2, 0, -1 / r2);
        assertVector(camera.heightVector(), 1 / r6, -2 / r6, 1 / r6);
        assertThat(camera.widthVector().dot(camera.heightVector())).isCloseTo(0f, within(1e-6f));
        assertThat(camera.widthVector().dot(camera.direction())).isCloseTo(0f, within(1e-6f));
    }

    @Test
    void eachRayStartsAtItsPixelsCornerAndKeepsTheGivenDirection() {
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -3), 50);
        Ray centre = camera.generateRay(960, 540, 1920, 1080);
        assertThat(centre.origin()).isEqualTo(new Vector3f(0, 0, 20));
        assertThat(centre.direction()).isEqualTo(new Vector3f(0, 0, -3));
        Ray topLeft = camera.generateRay(0, 0, 1920, 1080);
        assertThat(topLeft.origin()).isEqualTo(new Vector3f(-960 / 50f, 540 / 50f, 20));
        // Odd sizes: integer division puts the centre ray on pixel (w/2, h/2).
        assertThat(camera.generateRay(2, 1, 5, 3).origin()).isEqualTo(new Vector3f(0, 0, 20));
    }

    @Test
    void lookingStraightDownKeepsWorldXRightAndGivesNoNaN() {
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 10, 0), new Vector3f(0, -1, 0), 10);
        assertVector(camera.widthVector(), 1, 0, 0);
        assertVector(camera.heightVector(), 0, 0, 1);
        assertThat(camera.generateRay(0, 0, 100, 100).origin().isFinite()).isTrue();
    }

    @Test
    void lookingStraightUpIsTheLimitOfTiltingTheDefaultViewUp() {
        OrthographicCamera camera = new OrthographicCamera(Vector3f.ZERO, new Vector3f(0, 5, 0), 10);
        assertVector(camera.widthVector(), 1, 0, 0);
        assertVector(camera.heightVector(), 0, 0, -1);
        OrthographicCamera almostUp = new OrthographicCamera(Vector3f.ZERO, new Vector3f(0, 1, -1e-3f), 10);
        assertVector(almostUp.heightVector(), 0, -1e-3, -1);
    }
}
