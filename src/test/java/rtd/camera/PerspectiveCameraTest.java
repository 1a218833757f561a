package rtd.camera;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The perspective camera (section 3.2.1)")
class PerspectiveCameraTest {

    private final PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(1, 2, 20), new Vector3f(0, 0, -3), 90);

    @Test
    void everyRayStartsAtTheCamerasPosition() {
        assertThat(camera.generateRay(0, 0, 640, 480).origin()).isEqualTo(new Vector3f(1, 2, 20));
        assertThat(camera.generateRay(639, 479, 640, 480).origin()).isEqualTo(new Vector3f(1, 2, 20));
    }

    @Test
    void theCentreRayIsTheViewDirection() {
        Ray centre = camera.generateRay(320, 240, 640, 480);
        assertThat(centre.direction().normalize()).isEqualTo(new Vector3f(0, 0, -1));
    }

    @Test
    void theImagesLeftEdgeLiesHalfTheFieldOfViewAside() {
        // A fov of 90 degrees: f = 320 / tan(45°) = 320 pixels, so the ray of x = 0 (x' = −320) runs at 45°.
        Ray left = camera.generateRay(0, 240, 640, 480);
        assertThat(left.direction().x()).isCloseTo(-320f, within(1e-3f));
        assertThat(left.direction().z()).isCloseTo(-320f, within(1e-3f));
        PerspectiveCamera narrow = new PerspectiveCamera(Vector3f.ZERO, new Vector3f(0, 0, -1), 60);
        Ray edge = narrow.generateRay(0, 50, 100, 100);
        double angle = Math.toDegrees(Math.atan2(-edge.direction().x(), -edge.direction().z()));
        assertThat(angle).isCloseTo(30.0, within(1e-4));
    }

    @Test
    void anObjectAtTheImageBorderIsWhereTheTangentOfHalfTheFieldOfViewSaysItIs() {
        // At distance 10 a 90° view spans x from −10 to 10: a sphere centred on x = −10 covers the left edge.
        PerspectiveCamera eye = new PerspectiveCamera(new Vector3f(0, 0, 10), new Vector3f(0, 0, -1), 90);
        Sphere onTheBorder = new Sphere(new Vector3f(-10, 0, 0), 0.5f, Color.BLACK);
        assertThat(onTheBorder.intersect(eye.generateRay(0, 50, 100, 100)).happened()).isTrue();
        assertThat(onTheBorder.intersect(eye.generateRay(5, 50, 100, 100)).happened()).as("10 % inside").isFalse();
    }

    @Test
    void worldYIsUpAndWorldXIsRightForTheDefaultView() {
        assertThat(camera.widthVector().subtract(new Vector3f(1, 0, 0)).magnitude()).isZero();
        assertThat(camera.heightVector().subtract(new Vector3f(0, -1, 0)).magnitude()).isZero();
        Ray topLeft = camera.generateRay(0, 0, 640, 480);
        assertThat(topLeft.direction().x()).isNegative();
        assertThat(topLeft.direction().y()).isPositive();
    }

    @Test
    void bothCamerasGiveTheSameRayForAWholeNumberAsForThePixel() {
        OrthographicCamera paper = new OrthographicCamera(new Vector3f(0.3f, 0, 20), new Vector3f(-1, -2, -3), 37);
        for (int x = 0; x < 641; x += 37) {
            for (int y = 0; y < 481; y += 41) {
                assertThat(paper.generateRay((float) x, (float) y, 641, 481)).isEqualTo(paper.generateRay(x, y, 641, 481));
                assertThat(camera.generateRay((float) x, (float) y, 641, 481)).isEqualTo(camera.generateRay(x, y, 641, 481));
            }
        }
    }

    @Test
    void aFractionReachesIntoThePixel() {
        Ray corner = camera.generateRay(10, 20, 640, 480);
        Ray inside = camera.generateRay(10.5f, 20.5f, 640, 480);
        assertThat(inside.direction().x() - corner.direction().x()).isCloseTo(0.5f, within(1e-4f));
        assertThat(inside.direction().y() - corner.direction().y()).isCloseTo(-0.5f, within(1e-4f));
    }

    /**
     * {@code perspective_camera:(0|3|10):(at 0|0|0):(60)}: the direction is the point minus the
     * position, (0|−3|−10), and every ray is that of the camera given that direction.
     */
    @Test
    void aCameraThatLooksAtAPointTakesThePointMinusItsPositionAsItsDirection() {
        Vector3f position = new Vector3f(0, 3, 10);
        PerspectiveCamera looking = PerspectiveCamera.lookingAt(position, Vector3f.ZERO, 60);
        PerspectiveCamera given = new PerspectiveCamera(position, new Vector3f(0, -3, -10), 60);
        assertThat(looking.direction()).isEqualTo(new Vector3f(0, -3, -10));
        assertThat(looking.target()).isEqualTo(Vector3f.ZERO);
        assertThat(given.target()).isNull();
        OrthographicCamera flat = OrthographicCamera.lookingAt(position, new Vector3f(1, 0, 0), 50);
        assertThat(flat.direction()).isEqualTo(new Vector3f(1, -3, -10));
        for (int x = 0; x < 640; x += 71) {
            assertThat(looking.generateRay(x, x / 2, 640, 480)).isEqualTo(given.generateRay(x, x / 2, 640, 480));
            assertThat(flat.generateRay(x, x / 2, 640, 480))
                    .isEqualTo(new OrthographicCamera(position, new Vector3f(1, -3, -10), 50).generateRay(x, x / 2, 640, 480));
        }
    }
}
