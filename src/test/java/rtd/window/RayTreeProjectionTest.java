package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.explain.RayTree;
import rtd.explain.RayTree.Kind;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.Scenes;

@DisplayName("A pixel's ray tree projected into the picture")
class RayTreeProjectionTest {

    private static final Vector3f BACK = new Vector3f(0, 0, 1);

    @Test
    void theOrthographicProjectionUndoesListing41() {
        // zoom 50 from (0, 0, 20) along −z, 160 × 90: the point (1, −0.5, 3) lies 50 right and 25 down of (80, 45)
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50);
        double[] at = new RayTreeProjection(camera, 160, 90).project(new Vector3f(1, -0.5f, 3));
        assertThat(at[0]).isCloseTo(130, within(1e-4));
        assertThat(at[1]).isCloseTo(70, within(1e-4));
    }

    @Test
    void thePerspectiveProjectionDividesByDepth() {
        // 90° over 160 pixels: f = 80; the point (1, 1, −2) is 2 ahead: 80·1/2 = 40 right and 40 up of (80, 45)
        PerspectiveCamera camera = new PerspectiveCamera(Vector3f.ZERO, new Vector3f(0, 0, -1), 90);
        double[] at = new RayTreeProjection(camera, 160, 90).project(new Vector3f(1, 1, -2));
        assertThat(at[0]).isCloseTo(120, within(1e-3));
        assertThat(at[1]).isCloseTo(5, within(1e-3));
    }

    @Test
    void theCameraRayRunsFromItsPixelToItsHitOnThePixelBothCameras() {
        // the paper's scene at a twelfth of its zoom, so that 160 × 90 shows what 1920 × 1080 does: the blue sphere
        // at (3, 8) lies 50/12·3 = 12.5 right and 50/12·8 = 33.3 up of (80, 45), at pixel (92, 12)
        Scene paper = Scenes.example("input_rtd");
        OrthographicCamera far = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50f / 12);
        Scene small = new Scene(paper.ambient(), far, paper.objects(), paper.lights());
        int[][] pixels = {{92, 12}, {90, 60}};
        Scene[] scenes = {small, Scenes.example("glass_and_mirror")};
        for (int i = 0; i < scenes.length; i++) {
            int x = pixels[i][0];
            int y = pixels[i][1];
            RayTree tree = RayTree.of(scenes[i], x, y, 160, 90);
            RayTreeProjection.Line camera = new RayTreeProjection(scenes[i].camera(), 160, 90).lines(tree).get(0);
            assertThat(camera.kind()).isEqualTo(Kind.CAMERA);
            assertThat(camera.ends()).isTrue();
            // the ray leaves the pixel's corner and its hit lies on that ray: it projects there
            assertThat(camera.x1()).isCloseTo(x, within(1e-2));
            assertThat(camera.y1()).isCloseTo(y, within(1e-2));
        }
    }

    @Test
    void aShadedPixelsTreeHasItsShadowReflectedAndRefractedRays() {
        // pixel (100, 50) of 160 × 90 looks at the glass sphere: it reflects, refracts and casts shadow rays
        Scene scene = Scenes.example("glass_and_mirror");
        List<RayTree.Segment> segments = RayTree.of(scene, 100, 50, 160, 90).segments();
        assertThat(segments).extracting(RayTree.Segment::kind).contains(Kind.CAMERA, Kind.REFLECTED, Kind.REFRACTED)
                .containsAnyOf(Kind.SHADOW_LIT, Kind.SHADOW_BLOCKED);
        assertThat(segments.get(0).depth()).isZero();
        assertThat(segments).filteredOn(s -> s.kind() == Kind.REFRACTED).allMatch(s -> s.depth() >= 1);
        // a lit shadow ray ends at its light
        assertThat(segments).filteredOn(s -> s.kind() == Kind.SHADOW_LIT).allMatch(s ->
                scene.lights().stream().anyMatch(light -> light.position().equals(s.to())));
        List<RayTreeProjection.Line> lines = new RayTreeProjection(scene.camera(), 160, 90)
                .lines(new RayTree(segments));
        assertThat(lines).isNotEmpty().allMatch(l -> Double.isFinite(l.x0()) && Double.isFinite(l.y1()));
    }

    @Test
    void aRayBehindThePerspectiveEyeIsCutAtIt() {
        PerspectiveCamera camera = new PerspectiveCamera(Vector3f.ZERO, new Vector3f(0, 0, -1), 90);
        RayTree behind = new RayTree(List.of(
                new RayTree.Segment(Kind.REFLECTED, new Vector3f(0, 0, 2), new Vector3f(0, 0, 5), BACK, 1),
                new RayTree.Segment(Kind.REFLECTED, new Vector3f(1, 0, -2), new Vector3f(1, 0, 2), BACK, 1),
                new RayTree.Segment(Kind.REFLECTED, new Vector3f(1, 0, 2), new Vector3f(1, 0, -2), BACK, 1)));
        List<RayTreeProjection.Line> lines = new RayTreeProjection(camera, 160, 90).lines(behind);
        assertThat(lines).hasSize(2); // the first lies wholly behind the eye
        assertThat(lines.get(0).ends()).isFalse(); // its end was cut off
        assertThat(lines.get(0).x0()).isCloseTo(120, within(1e-3)); // f = 80: x = 80 + 80 · 1/2
        // the last starts behind the eye: cut just ahead of it, far off the picture's right edge, to its end at 120
        assertThat(lines.get(1).ends()).isTrue();
        assertThat(lines.get(1).x1()).isCloseTo(120, within(1e-3));
        assertThat(lines.get(1).x0()).isGreaterThan(160);
    }
}
