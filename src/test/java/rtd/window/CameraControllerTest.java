package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The window's camera: orbit, pan, zoom and reset, for both cameras")
class CameraControllerTest {

    private static final Vector3f PIVOT = new Vector3f(0, 0, 0);
    private final PerspectiveCamera perspective = new PerspectiveCamera(new Vector3f(0, 2.5f, 9),
            new Vector3f(0, -0.3f, -1), 60);
    private final OrthographicCamera orthographic = new OrthographicCamera(new Vector3f(0, 0, 20),
            new Vector3f(0, 0, -1), 50);

    @Test
    void orbitingAFullTurnReturnsToTheStart() {
        for (ICamera camera : new ICamera[] {perspective, orthographic}) {
            CameraController controller = new CameraController(camera);
            for (int step = 0; step < 36; step++) {
                controller.orbit(Math.toRadians(10), 0, new Vector3f(1, 0.5f, -2));
            }
            assertSameRays(controller.camera(), camera);
        }
    }

    @Test
    void orbitingUpAndBackDownReturnsToTheStart() {
        CameraController controller = new CameraController(perspective);
        controller.orbit(0, Math.toRadians(30), PIVOT);
        controller.orbit(Math.toRadians(45), 0, PIVOT);
        controller.orbit(Math.toRadians(-45), 0, PIVOT);
        controller.orbit(0, Math.toRadians(-30), PIVOT);
        assertSameRays(controller.camera(), perspective);
    }

    @Test
    void aQuarterTurnAboutTheVerticalLooksAtThePivotFromTheSide() {
        // from (0, 0, 20) looking along −z at the origin; a quarter turn to the left: at (−20, 0, 0), along +x
        CameraController controller = new CameraController(orthographic);
        controller.orbit(-Math.PI / 2, 0, PIVOT);
        OrthographicCamera turned = (OrthographicCamera) controller.camera();
        assertClose(turned.position(), new Vector3f(-20, 0, 0));
        assertClose(turned.direction(), new Vector3f(1, 0, 0));
        assertThat(turned.zoom()).isEqualTo(50f);
    }

    @Test
    void orbitingKeepsThePivotAtTheSameSpotOfThePicture() {
        // the pivot on the centre pixel's ray stays at the centre, (480, 270), however the camera turns
        Vector3f pivot = perspective.generateRay(480, 270, 960, 540).pointAt(9);
        CameraController controller = new CameraController(perspective);
        controller.orbit(0.7, 0.3, pivot);
        double[] at = new RayTreeProjection(controller.camera(), 960, 540).project(pivot);
        assertThat(at[0]).isCloseTo(480, within(1e-2));
        assertThat(at[1]).isCloseTo(270, within(1e-2));
    }

    @Test
    void thePitchStopsShortOfLookingStraightDown() {
        CameraController controller = new CameraController(orthographic);
        controller.orbit(0, Math.toRadians(200), PIVOT);
        OrthographicCamera steep = (OrthographicCamera) controller.camera();
        double elevation = Math.toDegrees(Math.asin(steep.direction().normalize().y()));
        assertThat(elevation).isCloseTo(-CameraController.STEEPEST_DEGREES, within(1e-3));
        assertThat(steep.position().y()).isGreaterThan(19.99f); // above the pivot, looking down on it
    }

    @Test
    void panningMovesThePictureWithTheMouse() {
        // dragged 10 pixels right and 5 down, a point at the pivot's depth moves by as much in the picture
        for (ICamera camera : new ICamera[] {perspective, orthographic}) {
            Vector3f pivot = camera.generateRay(480, 270, 960, 540).pointAt(camera == perspective ? 9 : 20);
            double[] before = new RayTreeProjection(camera, 960, 540).project(pivot);
            CameraController controller = new CameraController(camera);
            controller.pan(10, 5, pivot, 960);
            double[] after = new RayTreeProjection(controller.camera(), 960, 540).project(pivot);
            assertThat(after[0] - before[0]).isCloseTo(10, within(1e-2));
            assertThat(after[1] - before[1]).isCloseTo(5, within(1e-2));
        }
    }

    @Test
    void theWheelZoomsTheOrthographicCameraAndMovesThePerspectiveOneAlongItsView() {
        CameraController ortho = new CameraController(orthographic);
        ortho.zoom(2, PIVOT);
        assertThat(((OrthographicCamera) ortho.camera()).zoom()).isCloseTo(50 * 1.21f, within(1e-4f));
        assertThat(ortho.camera().position()).isEqualTo(orthographic.position());

        // 10 ahead along the view: one click in leaves 10 / 1.1 to go, along the same direction
        Vector3f ahead = perspective.position().add(perspective.forward().multiply(10));
        CameraController persp = new CameraController(perspective);
        persp.zoom(1, ahead);
        PerspectiveCamera nearer = (PerspectiveCamera) persp.camera();
        assertThat(ahead.subtract(nearer.position()).magnitude()).isCloseTo(10 / 1.1f, within(1e-4f));
        assertClose(nearer.forward(), perspective.forward());
        assertThat(nearer.fieldOfView()).isEqualTo(60f);
    }

    @Test
    void theFilesOwnCameraUntilItIsMoved() {
        CameraController controller = new CameraController(perspective);
        assertThat(controller.moved()).isFalse();
        assertThat(controller.camera()).isSameAs(perspective);
        controller.orbit(1, 0.2, PIVOT);
        controller.pan(3, 4, PIVOT, 960);
        controller.zoom(-3, PIVOT);
        assertThat(controller.moved()).isTrue();
        assertThat(controller.camera()).isNotSameAs(perspective);
    }

    /** The two cameras make nearly the same ray for a few pixels (floats: not to the last bit). */
    private static void assertSameRays(ICamera actual, ICamera expected) {
        int[][] pixels = {{0, 0}, {480, 270}, {959, 539}, {100, 400}};
        for (int[] p : pixels) {
            Ray a = actual.generateRay(p[0], p[1], 960, 540);
            Ray e = expected.generateRay(p[0], p[1], 960, 540);
            assertClose(a.origin(), e.origin());
            assertClose(a.direction().normalize(), e.direction().normalize());
        }
    }

    private static void assertClose(Vector3f actual, Vector3f expected) {
        assertThat(actual.subtract(expected).magnitude()).as(actual + " ≈ " + expected).isLessThan(1e-4f);
    }
}
