package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** A picture of background alone, or of one plane the camera stands in, gets a one-line warning that names the likely cause; the exit code stays 0. */
@DisplayName("The warning when nothing is in view")
class NothingInViewTest {

    @TempDir
    Path dir;

    private Run render(String scene, String... options) throws IOException {
        Path file = Files.writeString(dir.resolve("scene.txt"), scene);
        java.util.List<String> args = new java.util.ArrayList<>(
                java.util.List.of(file.toString(), "-o", dir.resolve("out.png").toString()));
        args.addAll(java.util.List.of(options));
        Run run = Cli.run(args.toArray(String[]::new));
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(dir.resolve("out.png")).isRegularFile();
        return run;
    }

    /** The warning as the catalogue shows it: for scene.txt, and present there word for word. */
    private String warning(Run run) {
        String line = Docs.firstLine(run.err(), dir);
        assertThat(run.err().lines()).hasSize(1);
        assertThat(Docs.errors()).contains(line);
        return line;
    }

    @Test
    void aCameraThatStandsInAPlaneIsNamedWithThePlane() throws IOException {
        String scene = "perspective_camera:(0|0|20):(0|0|-1):(88)\nsphere:(3|8|-1):(2):(0|127|255)\n"
                + "sphere:(-10|1|5):(5):(255|0|0)\nplane:(0|0|0):(0|1|0):(200|200|200)\n";
        assertThat(warning(render(scene, "--width", "64", "--height", "36"))).isEqualTo("rtd: warning: scene.txt: the "
                + "camera stands in plane #3 (through (0|0|0), normal (0|1|0)): every ray that leaves it hits that plane at "
                + "distance 0, so the picture shows that plane alone; move the camera or the plane a little");
        assertThat(render(scene.replace("plane:(0|0|0)", "plane:(0|-0.001|0)"), "--width", "64", "--height", "36").err())
                .isEmpty();
        // the orthographic camera's rays start in the plane of its image: a plane there catches them all
        assertThat(render("orthographic_camera:(0|0|20):(0|0|-1):(50)\nplane:(0|0|20):(0|0|1):(9|9|9)\n"
                + "sphere:(0|0|0):(1):(255|0|0)\n", "--width", "64", "--height", "36").err())
                .contains("the camera stands in plane #1 (through (0|0|20), normal (0|0|1))");
    }

    @Test
    void objectsBehindTheCameraAreNamedAsTheCause() throws IOException {
        Run run = render("orthographic_camera:(0|0|20):(0|0|1):(50)\nsphere:(3|8|-1):(2):(0|127|255)\n"
                + "sphere:(-10|1|5):(5):(255|0|0)\n");
        assertThat(warning(run)).isEqualTo("rtd: warning: scene.txt: no ray hit anything, so the picture is only "
                + "background: all 2 objects are behind the camera, which looks along (0|0|1) from (0|0|20)");
    }

    @Test
    void objectsOutsideTheVisibleRegionGetTheRegionInWorldUnits() throws IOException {
        Run run = render("orthographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(30|0|0):(2):(0|127|255)\n");
        assertThat(warning(run)).isEqualTo("rtd: warning: scene.txt: no ray hit anything, so the picture is only "
                + "background: the camera sees 38.4 × 21.6 world units around (0|0|20) (width/zoom × height/zoom), and no "
                + "object is in that region; move the camera, or lower its zoom to see more");
    }

    @Test
    void theRegionFollowsTheSizeAndTheScale() throws IOException {
        String scene = "orthographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(30|0|0):(2):(0|127|255)\n";
        assertThat(render(scene, "--width", "300", "--height", "200").err()).contains("sees 6 × 4 world units");
        assertThat(render(scene, "--scale", "0.5").err()).contains("sees 38.4 × 21.6 world units");
    }

    @Test
    void objectsThatFallBetweenTheRaysAreSaidToDoSo() throws IOException {
        Run run = render("orthographic_camera:(0|0|20):(0|0|-1):(0.01)\nsphere:(50.5|50.5|0):(0.1):(0|127|255)\n");
        assertThat(warning(run)).isEqualTo("rtd: warning: scene.txt: no ray hit anything, so the picture is only "
                + "background: the camera sees 192000 × 108000 world units around (0|0|20) (width/zoom × height/zoom), and "
                + "the objects there fall between its rays, which are 100 world units apart (1/zoom); raise the zoom");
    }

    @Test
    void aSceneWithoutObjectsIsSaidToHaveNone() throws IOException {
        Run run = render("orthographic_camera:(0|0|20):(0|0|-1):(50)\n");
        assertThat(warning(run)).isEqualTo("rtd: warning: scene.txt: no ray hit anything, so the picture is only "
                + "background: the scene has no objects");
    }

    @Test
    void thePapersOwnRendererWarnsAlike() throws IOException {
        Run run = render("orthographic_camera:(0|0|20):(0|0|1):(50)\nsphere:(3|8|-1):(2):(0|127|255)\n", "--paper",
                "--width", "64", "--height", "36");
        assertThat(run.err()).contains("the one object is behind the camera");
    }

    @Test
    void aPictureWithAnObjectInViewGetsNoWarning() throws IOException {
        assertThat(render("orthographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(0|0|0):(2):(0|127|255)\n").err()).isEmpty();
    }

    @Test
    void anObjectInTheBackgroundsColourIsSeenAsAHitAndAloneOutOfViewIsNot() throws IOException {
        String camouflaged = "ambient:(1|2|3)\northographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(0|0|0):(2):(1|2|3)\n";
        assertThat(render(camouflaged).err()).isEmpty();
        assertThat(render(camouflaged.replace("(0|0|0)", "(90|0|0)")).err()).contains("no ray hit anything");
    }

    @Test
    @DisplayName("--width and --height of the paper's shape that show nothing are offered the --scale that shows the "
            + "paper's view at that size")
    void aSmallerSizeOfThePapersShapeIsOfferedTheScale() throws IOException {
        Path example = Path.of("examples", "input_rtd.txt");
        String scene = Files.readString(example);
        Run run = render(scene, "--width", "480", "--height", "270");
        // 480/50 = 9.6 and 270/50 = 5.4 world units around (0|0|20); at 1920×1080 the spheres are in view
        assertThat(warning(run)).isEqualTo("rtd: warning: scene.txt: no ray hit anything, so the picture is only "
                + "background: the camera sees 9.6 × 5.4 world units around (0|0|20) (width/zoom × height/zoom), and no "
                + "object is in that region; move the camera, or lower its zoom to see more; or, to see at 480×270 what "
                + "1920×1080 shows, give --scale 0.25 in place of --width and --height");
        assertThat(render(scene, "--scale", "0.25").err()).isEmpty();
        // another shape, or a view that the default size would not show either: no --scale to offer
        assertThat(render(scene, "--width", "480", "--height", "300").err()).doesNotContain("--scale");
        assertThat(render("orthographic_camera:(0|0|20):(0|0|-1):(50)\nsphere:(30|0|0):(2):(0|127|255)\n", "--width",
                "480", "--height", "270").err()).doesNotContain("--scale");
    }

    @Test
    void aFloorThatTheOrthographicCameraLooksAlongIsNamedWithTheWayToSeeIt() throws IOException {
        Run run = render("orthographic_camera:(0|5|20):(0|0|-1):(50)\nplane:(0|0|0):(0|1|0):(0|0|0)\n");
        assertThat(warning(run)).isEqualTo("rtd: warning: scene.txt: no ray hit anything, so the picture is only "
                + "background: the camera's rays from (0|5|20) along (0|0|-1) run parallel to the plane or away from it; "
                + "tilt the camera towards it, as (0|-1|-1) looks down onto a floor");
    }

    @Test
    void aFloorBelowAPerspectiveCameraThatLooksUpIsOutsideItsFieldOfView() throws IOException {
        Run run = render("perspective_camera:(0|5|20):(0|1|0):(60)\nplane:(0|0|0):(0|1|0):(200|0|0)\n"
                + "plane:(0|-1|0):(0|1|0):(0|200|0)\n");
        assertThat(warning(run)).isEqualTo("rtd: warning: scene.txt: no ray hit anything, so the picture is only "
                + "background: all 2 planes lie outside the camera's field of view from (0|5|20) along (0|1|0); turn the "
                + "camera towards them");
    }
}
