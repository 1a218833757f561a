package rtd.pov;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.io.SceneIO;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.scene.Scene;
import rtd.shade.WhittedShader;
import rtd.testing.ImageComparison;
import rtd.testing.Renders;
import rtd.testing.Scenes;

/** Patterns and transformations exported to POV-Ray: a function pattern per rule, a matrix per transform. */
@DisplayName("The POV-Ray export of patterns and transformations")
class PovPatternsTest {

    private static final String SHAPES = String.join("\n",
            "ambient:(20|30|60)",
            "perspective_camera:(0|4|12):(at 0|0.5|0):(55)",
            "transform:(egg):(scale 1.6|0.8|1):(rotate_y 30):(translate -3|1|0)",
            "transform:(tilt):(rotate_z 25):(rotate_x -15):(translate 3|1|0)",
            "transform:(small):(scale 0.4)",
            "pattern:(checks):(checker):(230|30|20):(250|220|40):(small)",
            "pattern:(bands):(stripes):(30|90|200):(240|240|240):(small)",
            "pattern:(glow):(gradient):(0|0|0):(255|128|0)",
            "pattern:(targets):(rings):(255|255|255):(90|90|90):(small)",
            "plane:(0|0|0):(0|1|0):(checks)",
            "sphere:(0|0|0):(1):(bands):(egg)",
            "box:(-1|-1|-1):(1|1|1):(glow):(tilt)",
            "triangle:(-2|0|-3):(2|0|-3):(0|3|-3):(targets)", "");

    @TempDir
    Path dir;

    @Test
    void aTransformIsItsMatrixAfterThePigment() throws Exception {
        Scene scene = SceneIO.parseScene("t.txt", "orthographic_camera:(0|0|20):(0|0|-1):(50)\n"
                + "transform:(t):(scale 2|1|1):(translate 1|2|3)\nsphere:(0|0|0):(1):(255|0|0):(t)\n");
        // x' = 2x + 1, y' = y + 2, z' = z + 3: POV-Ray's numbers are M's columns, the translation last
        assertThat(PovScene.of(scene, 64, 48, "t.pov"))
                .contains("sphere { <0, 0, 0>, 1 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } "
                        + "matrix <2, 0, 0, 0, 1, 0, 0, 0, 1, 1, 2, 3> }");
    }

    @Test
    void aCheckerIsAFunctionOfThePointJustBeneathTheSurface() throws Exception {
        Scene scene = SceneIO.parseScene("c.txt", "orthographic_camera:(0|0|20):(0|0|-1):(50)\n"
                + "pattern:(c):(checker):(255|0|0):(0|0|255)\nplane:(0|0|0):(0|1|0):(c)\n");
        assertThat(PovScene.of(scene, 64, 48, "c.pov")).contains("pigment { function { 0.5*abs(mod(floor(",
                "(y - 0.0001)", "color_map { [0.25 rgb <1, 0, 0>] [0.25 rgb <0, 0, 1>] }");
    }

    @Test
    void patternedAndTransformedShapesDrawTheSameFlatPictureInPovRay() throws Exception {
        PovRay.assumeInstalled();
        Files.copy(Path.of("examples", "meshes", "icosphere_1.obj"), dir.resolve("ico.obj"));
        Scene scene = SceneIO.parseScene("shapes.txt", (SHAPES + "mesh:(ico.obj):(0|0.8|2):(0.8):(bands):(small)\n")
                .getBytes(java.nio.charset.StandardCharsets.UTF_8), dir, null);
        BufferedImage rtd = Renders.parallel(scene, 160, 90, 2, true).image().toBufferedImage();
        ImageComparison.Result result = ImageComparison.EDGE_TOLERANT.compare(rtd, povRay(scene, 160, 90));
        assertThat(result.matches()).as(result.summary()).isTrue();
    }

    /**
     * Whitted's picture, shaded, glass and mirror: at most 2 % of the pixels may differ by more than 8
     * levels (1.4 % at 240 × 135: (the glass's Fresnel mix, shadow edges, the tiles' edges seen through the glass)).
     */
    @Test
    void whittedsPictureDrawsNearlyTheSameInPovRay() throws Exception {
        PovRay.assumeInstalled();
        Scene scene = Scenes.example("whitted_1980");
        int w = 240;
        int h = 135;
        BufferedImage rtd = ParallelRenderer.render(scene.camera(), () -> new LinearTracer(scene),
                tracer -> new WhittedShader(scene, tracer), w, h, 2, new RenderProgress()).image().toBufferedImage();
        BufferedImage pov = povRay(scene, w, h);
        int far = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                far += differ(rtd.getRGB(x, y), pov.getRGB(x, y)) > 8 ? 1 : 0;
            }
        }
        assertThat(far).as("pixels more than 8 levels apart").isLessThanOrEqualTo(w * h * 2 / 100);
    }

    private BufferedImage povRay(Scene scene, int w, int h) throws Exception {
        Files.writeString(dir.resolve("scene.pov"), PovScene.of(scene, w, h, "scene.pov"));
        return PovRay.render(dir, "scene.pov", w, h);
    }

    private static int differ(int a, int b) {
        int most = 0;
        for (int shift = 0; shift < 24; shift += 8) {
            most = Math.max(most, Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF)));
        }
        return most;
    }
}
