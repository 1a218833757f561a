package rtd.pov;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.scene.Light;
import rtd.scene.Scene;
import rtd.shade.WhittedShader;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.testing.ImageComparison;
import rtd.testing.MixedScenes;
import rtd.testing.RandomScenes;
import rtd.testing.Renders;
import rtd.testing.Scenes;

@DisplayName("The POV-Ray export")
class PovSceneTest {

    @TempDir
    Path dir;

    private BufferedImage povRay(Scene scene, int w, int h) throws Exception {
        Files.writeString(dir.resolve("scene.pov"), PovScene.of(scene, w, h, "scene.pov"));
        return PovRay.render(dir, "scene.pov", w, h);
    }

    private static BufferedImage rtd(Scene scene, int w, int h) {
        return Renders.parallel(scene, w, h, 2, true).image().toBufferedImage();
    }

    @Test
    void startsWithThePovrayCommandThatRendersItAtRtdsSize() {
        String pov = PovScene.of(Scenes.example("input_rtd"), 1920, 1080, "paper.pov");
        assertThat(pov.lines().findFirst()).hasValueSatisfying(line -> assertThat(line).startsWith("//"));
        assertThat(pov).contains("povray +Ipaper.pov +Opaper-pov.png +W1920 +H1080 +FN -A -D File_Gamma=1.0",
                "assumed_gamma 1.0", "ambient_light rgb <1, 1, 1>", "finish { ambient 1 diffuse 0 }", "orthographic",
                "sphere { <-10, 1, 5>, 5 pigment { rgb <1, 0, 0> }");
        assertThat(pov).doesNotContain("light_source");
    }

    @Test
    void aShadedSceneGetsLightsFinishesAndTheTraceLevel() {
        String pov = PovScene.of(shadedScene(), 64, 48, "s.pov");
        assertThat(pov).contains("light_source { <-6, 8, 9>, rgb <1, 1, 1> }", "max_trace_level 6 adc_bailout 0",
                "phong_size 200", "reflection { 0.4 }", "ambient_light rgb <1.3137255, 1.3137255, 1.3137255>",
                "perspective");
    }

    @Test
    void thePapersExampleDrawsTheSamePictureInPovRay() throws Exception {
        PovRay.assumeInstalled();
        Scene scene = Scenes.example("input_rtd");
        assertSameFlatPicture(rtd(scene, 1920, 1080), povRay(scene, 1920, 1080));
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2})
    void randomFlatScenesOfEveryKindOfObjectAndBothCamerasDrawTheSamePicture(long seed) throws Exception {
        PovRay.assumeInstalled();
        for (Scene scene : List.of(MixedScenes.generate(seed, 40), RandomScenes.generate(seed, 40))) {
            assertSameFlatPicture(rtd(scene, 160, 120), povRay(scene, 160, 120));
            assertSameFlatPicture(rtd(scene, 161, 121), povRay(scene, 161, 121)); // odd sizes: no half-pixel shift
        }
    }

    /**
     * A camera that looks at a point, of either kind, seen from off its axes: the export says
     * {@code look_at} and POV-Ray draws the same picture, at even and odd sizes.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"orthographic_camera:(4|3|12):(at 1|0|-1):(12)", "perspective_camera:(4|3|12):(at 1|0|-1):(50)"})
    void aCameraThatLooksAtAPointDrawsTheSamePictureWithLookAt(String camera) throws Exception {
        Scene scene = rtd.io.SceneIO.parseScene("at.txt", camera + "\nambient:(20|30|40)\nsphere:(1|0|-1):(2):(200|60|60)\n"
                + "box:(-4|-1|-4):(-2|2|-2):(60|200|60)\ntriangle:(3|-1|0):(5|-1|0):(4|2|-2):(60|60|200)\n");
        assertThat(PovScene.of(scene, 160, 120, "at.pov")).contains("look_at ");
        PovRay.assumeInstalled();
        assertSameFlatPicture(rtd(scene, 160, 120), povRay(scene, 160, 120));
        assertSameFlatPicture(rtd(scene, 161, 121), povRay(scene, 161, 121));
    }

    /** Straight down, POV-Ray's look_at has no right axis (it warns); the vectors alone give the same picture. */
    @Test
    void anOrthographicCameraLookingStraightDownAtAPointIsWrittenWithoutLookAt() throws Exception {
        Scene scene = rtd.io.SceneIO.parseScene("down.txt", "orthographic_camera:(1|10|-1):(at 1|0|-1):(12)\n"
                + "ambient:(20|30|40)\nsphere:(1|0|-1):(2):(200|60|60)\nbox:(-4.3|-1|-4.3):(-2.2|2|-2.2):(60|200|60)\n");
        assertThat(PovScene.of(scene, 160, 120, "down.pov")).doesNotContain("look_at");
        PovRay.assumeInstalled();
        assertSameFlatPicture(rtd(scene, 160, 120), povRay(scene, 160, 120));
    }

    /** Cylinders and cones, upright, tilted and with an apex, flat: POV-Ray's closed {@code cylinder} and {@code cone} draw the same. */
    @Test
    void cylindersAndConesDrawTheSamePictureAsPovRaysClosedOnes() throws Exception {
        Scene scene = rtd.io.SceneIO.parseScene("solids.txt", "perspective_camera:(0|3|10):(at 0|1|0):(50)\n"
                + "ambient:(20|30|40)\ncylinder:(-2|0|0):(-2|2|0):(1):(200|60|40)\ncone:(1.5|0|0):(1):(1.5|2.5|0):(0):(60|160|220)\n"
                + "cylinder:(0|0.5|2):(1|0.5|3):(0.4):(240|200|60)\ncone:(-1|0.3|3):(0.3):(0.5|1|3.5):(0.1):(120|220|90)\n");
        assertThat(PovScene.of(scene, 160, 120, "s.pov")).contains("cylinder { <-2, 0, 0>, <-2, 2, 0>, 1 pigment",
                "cone { <1.5, 0, 0>, 1, <1.5, 2.5, 0>, 0 pigment");
        PovRay.assumeInstalled();
        assertSameFlatPicture(rtd(scene, 160, 120), povRay(scene, 160, 120));
        assertSameFlatPicture(rtd(scene, 161, 121), povRay(scene, 161, 121));
    }

    /**
     * An area light of 4 × 4 over a sphere and a cylinder on a floor: POV-Ray's {@code area_light},
     * placed so that its 16 lights fall on rtd's samples, draws the same soft shadows. It shades
     * with the light's centre, where rtd sums its samples, so highlights and the edge between
     * light and dark differ a little: at most 1 % of the pixels may differ by more than 8 levels.
     */
    @Test
    void anAreaLightCastsTheSameSoftShadowsAsPovRaysAreaLight() throws Exception {
        Scene scene = rtd.io.SceneIO.parseScene("soft.txt", "perspective_camera:(0|4|10):(at 0|0.5|0):(50)\n"
                + "ambient:(20|30|50)\narea_light:(-1|6|-1):(2|0|0):(0|0|2):(4|4):(255|255|255)\n"
                + "plane:(0|0|0):(0|1|0):(200|200|200)\nsphere:(0|1|0):(1):(200|60|40)\n"
                + "cylinder:(2.5|0|0):(2.5|1.5|0):(0.5):(60|160|220)\n");
        int w = 240;
        int h = 135;
        assertThat(PovScene.of(scene, w, h, "soft.pov"))
                .contains("light_source { <0, 6, 0>, rgb <1, 1, 1> area_light <1.5, 0, 0>, <0, 0, 1.5>, 4, 4 }");
        PovRay.assumeInstalled();
        assertThat(pixelsApart(shaded(scene, w, h), povRay(scene, w, h), 8)).as("pixels more than 8 levels apart")
                .isLessThanOrEqualTo(w * h / 100);
    }

    private static void assertSameFlatPicture(BufferedImage rtd, BufferedImage pov) {
        ImageComparison.Result result = ImageComparison.EDGE_TOLERANT.compare(rtd, pov);
        assertThat(result.matches()).as(result.summary()).isTrue();
    }

    /**
     * Shaded, opaque, with mirrors: at most 2 % of the pixels may differ by more than 2 levels in
     * a channel (shadow and silhouette edges, and POV-Ray aiming shadow rays from P itself).
     */
    @Test
    void aShadedSceneWithMirrorsDrawsNearlyTheSamePicture() throws Exception {
        PovRay.assumeInstalled();
        Scene scene = shadedScene();
        int w = 160;
        int h = 120;
        assertThat(pixelsApart(shaded(scene, w, h), povRay(scene, w, h), 2)).as("pixels more than 2 levels apart")
                .isLessThanOrEqualTo(w * h / 50);
    }

    /**
     * Glass that also mirrors (the glass and mirror example): rtd mixes reflection and refraction
     * by Schlick, the export by POV-Ray's Fresnel reflection; at most 1 % of the pixels may differ
     * by more than 8 levels (0.24 % at 480 × 270; 16.5 % with a plain reflection added to the light let through).
     */
    @Test
    void glassThatAlsoMirrorsDrawsNearlyTheSamePictureByPovRaysFresnelReflection() throws Exception {
        Scene scene = Scenes.example("glass_and_mirror");
        int w = 240;
        int h = 135;
        assertThat(PovScene.of(scene, w, h, "g.pov")).contains("reflection { 0, 0.9 fresnel on } conserve_energy",
                "phong_size 300 reflection { 0.9 } }", "reflection { 0.15 }");
        PovRay.assumeInstalled();
        assertThat(pixelsApart(shaded(scene, w, h), povRay(scene, w, h), 8)).as("pixels more than 8 levels apart")
                .isLessThanOrEqualTo(w * h / 100);
    }

    /** rtd's shaded picture of {@code scene}, through the paper's loop. */
    private static BufferedImage shaded(Scene scene, int w, int h) {
        return ParallelRenderer.render(scene.camera(), () -> new LinearTracer(scene),
                tracer -> new WhittedShader(scene, tracer), w, h, 2, new RenderProgress()).image().toBufferedImage();
    }

    /** How many pixels differ by more than {@code levels} in some channel. */
    private static int pixelsApart(BufferedImage a, BufferedImage b, int levels) {
        int far = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                far += differ(a.getRGB(x, y), b.getRGB(x, y)) > levels ? 1 : 0;
            }
        }
        return far;
    }

    private static int differ(int a, int b) {
        int most = 0;
        for (int shift = 0; shift < 24; shift += 8) {
            most = Math.max(most, Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF)));
        }
        return most;
    }

    private static Scene shadedScene() {
        Material matt = Material.DEFAULT;
        Material mirror = new Material(0.1f, 0.6f, 0.9f, 200, 0.4f, 0, 1);
        List<IGeometry> objects = new ArrayList<>();
        objects.add(new Plane(new Vector3f(0, -1, 0), new Vector3f(0, 1, 0), new Color(200, 200, 180), matt));
        objects.add(new Sphere(new Vector3f(-1.2f, 0, 0), 1, new Color(220, 40, 40), mirror));
        objects.add(new Sphere(new Vector3f(1.3f, -0.3f, 0.8f), 0.7f, new Color(40, 200, 60), matt));
        objects.add(Box.between(new Vector3f(1.5f, -1, -2.5f), new Vector3f(2.8f, 0.6f, -1.2f), new Color(60, 80, 230), matt));
        objects.add(new Triangle(new Vector3f(-3, -1, -2), new Vector3f(-1.5f, 2, -2.5f), new Vector3f(0, -1, -3),
                new Color(230, 200, 40), matt));
        List<Light> lights = List.of(new Light(new Vector3f(-6, 8, 9), new Rgb(1, 1, 1)),
                new Light(new Vector3f(6, 4, 6), Rgb.of(new Color(80, 80, 80))));
        return new Scene(new Color(30, 30, 50), new PerspectiveCamera(new Vector3f(0, 1.5f, 7), new Vector3f(0, -0.2f, -1), 60),
                objects, lights);
    }
}
