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

/**
 * A scene that draws a picture without a word of why it looks wrong gets a line that says so: a light that is
 * almost black, a light or a camera inside a closed object, and the slips with materials; the picture is still
 * written.
 */
@DisplayName("The warnings about a scene's camera and lights")
class SceneWarningsTest {

    private static final String CAMERA_AND_BALL = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";

    @TempDir
    Path dir;

    private Run render(String scene) throws IOException {
        Path file = Files.writeString(dir.resolve("scene.txt"), scene);
        Run run = Cli.run(file.toString(), "-o", dir.resolve("out.png").toString(), "--width", "64", "--height", "36");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(dir.resolve("out.png")).isRegularFile();
        return run;
    }

    /** The line as the catalogue shows it: for scene.txt, and present there word for word. */
    private String line(Run run) {
        String line = Docs.firstLine(run.err(), dir);
        assertThat(run.err().lines()).hasSize(1);
        assertThat(Docs.errors()).contains(line);
        return line;
    }

    @Test
    void aLightOfOneLevelInEachChannelIsAlmostBlackAndSaysHowFullWhiteIsWritten() throws IOException {
        Run run = render(CAMERA_AND_BALL + "sphere:(0|0|0):(3):(255|0|0)\nlight:(0|0|10):(255|255|255)\nlight:(0|0|10):(1|1|0)\n");
        assertThat(line(run)).isEqualTo("rtd: warning: scene.txt: light #2 has the intensity (1|1|0), almost black: rtd's "
                + "colours run from 0 to 255, so a full white light is (255|255|255)");
        assertThat(render(CAMERA_AND_BALL + "sphere:(0|0|0):(3):(255|0|0)\nlight:(0|0|10):(2|1|1)\n").err())
                .as("two levels are dim, not a slip").isEmpty();
        assertThat(render(CAMERA_AND_BALL + "sphere:(0|0|0):(3):(255|0|0)\nlight:(0|0|10):(0|0|0)\n").err())
                .as("a light turned off").isEmpty();
    }

    /**
     * An area light of 16 × 16 white samples: each sample's share, 1/256, is below one level, and
     * no warning; one of (1|1|1) is almost black as a whole, told once. A sphere round the first
     * sample is told once too, not for each sample inside it.
     */
    @Test
    void anAreaLightIsWarnedOfOnceAsAWhole() throws IOException {
        String light = "area_light:(-1|4|0):(2|0|0):(0|0|2):(16|16):";
        assertThat(render(CAMERA_AND_BALL + "sphere:(0|0|0):(3):(255|0|0)\n" + light + "(255|255|255)\n").err()).isEmpty();
        assertThat(line(render(CAMERA_AND_BALL + "sphere:(0|0|0):(3):(255|0|0)\n" + light + "(1|1|1)\n")))
                .isEqualTo("rtd: warning: scene.txt: the area light with corner (-1|4|0) has the intensity (1|1|1), "
                        + "almost black: rtd's colours run from 0 to 255, so a full white light is (255|255|255)");
        assertThat(line(render(CAMERA_AND_BALL + "sphere:(0|4|0):(0.5):(200|0|0)\nsphere:(0|0|0):(3):(255|0|0)\n" + light
                + "(255|255|255)\n"))).startsWith("rtd: warning: scene.txt: a sample of the area light with corner (-1|4|0) "
                        + "at (-0.4375|4|0.0625) is inside sphere #1 (centre (0|4|0), radius 0.5)");
    }

    @Test
    void withPaperTheLightIsNotUsedAndItsDimnessNotTold() throws IOException {
        Path file = Files.writeString(dir.resolve("scene.txt"), CAMERA_AND_BALL + "sphere:(0|0|0):(3):(255|0|0)\n"
                + "light:(0|0|10):(1|1|1)\n");
        Run run = Cli.run(file.toString(), "-o", dir.resolve("out.png").toString(), "--width", "64", "--height", "36", "--paper");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("--paper draws as the paper does").doesNotContain("almost black");
    }

    @Test
    void materialSlipsAreToldAtTheMaterialsLineAndThePictureIsStillDrawn() throws IOException {
        Run run = render(CAMERA_AND_BALL + "material:(shiny):(reflective=0.5)\nsphere:(0|0|0):(3):(255|0|0):(shiny)\n");
        assertThat(Docs.firstLine(run.err(), dir)).startsWith("scene.txt:2:11: warning: materials change nothing here: "
                + "the scene has no light");
        assertThat(Docs.errors()).contains(Docs.firstLine(run.err(), dir));
        Run unused = render(CAMERA_AND_BALL + "light:(0|10|10):(255|255|255)\nmaterial:(glass):(transparency=0.9|ior=1.5)\n"
                + "sphere:(0|0|0):(3):(255|0|0)\n");
        assertThat(Docs.firstLine(unused.err(), dir)).isEqualTo("scene.txt:3:11: warning: material 'glass' is defined, "
                + "but no object names it");
        assertThat(unused.err()).doesNotContain("bends nothing");
        assertThat(render(CAMERA_AND_BALL + "material:(m):(reflective=0.5)\nsphere:(0|0|0):(3):(255|0|0):(m)\n"
                + "light:(0|0|10):(255|255|255)\n").err()).as("a lit scene whose material is named").isEmpty();
    }

    @Test
    @DisplayName("A light inside a sphere is said to light nothing outside it, with the sphere named")
    void aLightInsideASphereLightsNothingOutsideIt() throws IOException {
        Run run = render(CAMERA_AND_BALL + "light:(0|0|0):(255|255|255)\nplane:(0|-3|0):(0|1|0):(0|255|0)\n"
                + "sphere:(0|0|0):(2):(255|0|0)\n");
        assertThat(line(run)).isEqualTo("rtd: warning: scene.txt: light #1 at (0|0|0) is inside sphere #2 (centre "
                + "(0|0|0), radius 2): every point outside it is in its shadow, so the light lights nothing outside it; "
                + "move the light out of it");
    }

    @Test
    @DisplayName("A light inside a box is named with the box's corners; one just outside gets no warning")
    void aLightInsideABoxLightsNothingOutsideIt() throws IOException {
        String box = "box:(-1|-1|-1):(1|1|1):(255|0|0)\n";
        Run run = render(CAMERA_AND_BALL + "light:(0.5|0|0):(255|255|255)\n" + box);
        assertThat(run.err().strip()).isEqualTo("rtd: warning: " + dir.resolve("scene.txt") + ": light #1 at (0.5|0|0) is inside box #1 (from "
                + "(-1|-1|-1) to (1|1|1)): every point outside it is in its shadow, so the light lights nothing "
                + "outside it; move the light out of it");
        assertThat(render(CAMERA_AND_BALL + "light:(1|0|0):(255|255|255)\n" + box).err()).isEmpty();
    }

    @Test
    @DisplayName("A camera inside a sphere is said to show its inside in one colour, with either camera")
    void aCameraInsideASphereShowsItsInside() throws IOException {
        String sphere = "sphere:(0|0|20):(5):(255|0|0)\n";
        Run run = render(CAMERA_AND_BALL + sphere);
        assertThat(line(run)).isEqualTo("rtd: warning: scene.txt: the camera is inside sphere #1 (centre (0|0|20), "
                + "radius 5): every ray starts inside it, so the picture shows its inside, all in one colour; move the "
                + "camera out of it");
        assertThat(render("perspective_camera:(0|0|20):(0|0|-1):(60)\n" + sphere).err())
                .contains("the camera is inside sphere #1");
        // the orthographic camera's rays leave from the whole image plane: 64/50 = 1.28 units wide, not inside 0.5
        assertThat(render(CAMERA_AND_BALL + "sphere:(0|0|20):(0.5):(255|0|0)\n").err()).doesNotContain("inside");
    }

    @Test
    @DisplayName("A camera inside a box is said to show its inside in one colour")
    void aCameraInsideABoxShowsItsInside() throws IOException {
        Run run = render(CAMERA_AND_BALL + "sphere:(0|0|0):(1):(0|0|255)\nbox:(-5|-5|15):(5|5|25):(255|0|0)\n");
        assertThat(Docs.firstLine(run.err(), dir)).isEqualTo("rtd: warning: scene.txt: the camera is inside box #2 (from (-5|-5|15) to "
                + "(5|5|25)): every ray starts inside it, so the picture shows its inside, all in one colour; move the "
                + "camera out of it");
    }

    @Test
    @DisplayName("A room, a box that holds the camera, the light and a ball, is no mistake: no warning")
    void aRoomThatHoldsCameraLightAndObjectsGetsNoWarning() throws IOException {
        assertThat(render(CAMERA_AND_BALL + "light:(0|5|10):(255|255|255)\nbox:(-50|-50|-50):(50|50|50):(200|200|200)\n"
                + "sphere:(0|0|0):(2):(255|0|0)\n").err()).isEmpty();
    }

    @Test
    @DisplayName("A camera inside a sphere of a lit scene shows its inside shaded, so the warning says no more than that")
    void aCameraInsideASphereOfALitSceneIsNotSaidToShowOneColour() throws IOException {
        Run run = render(CAMERA_AND_BALL + "sphere:(0|0|20):(5):(255|0|0)\nlight:(0|0|21):(255|255|255)\n");
        assertThat(line(run)).isEqualTo("rtd: warning: scene.txt: the camera is inside sphere #1 (centre (0|0|20), "
                + "radius 5): every ray starts inside it, so the picture shows its inside; move the camera out of it");
    }
}
