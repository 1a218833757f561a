package rtd.explain;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.accel.Bvh;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.scene.Light;
import rtd.scene.Scene;
import rtd.shade.FlatShader;
import rtd.shade.WhittedShader;
import rtd.testing.MixedScenes;
import rtd.testing.RandomScenes;
import rtd.testing.Scenes;

@DisplayName("Explaining a pixel")
class PixelExplanationTest {

    private static final Pattern COLOUR = Pattern.compile("pixel colour: [^\\n]*?(\\d+) (\\d+) (\\d+)\\n");
    private static final Pattern NEAREST = Pattern.compile("   (nearest: #(\\d+)|no object is hit)");

    @Test
    void thePapersExampleOnTheRedSphereShowsEquations36To38AndTheColour() {
        String text = PixelExplanation.of(Scenes.example("input_rtd"), 460, 490, 1920, 1080);
        assertThat(text).contains("x' = x − w/2 = 460 − 960 = -500", "O = pos + u·x'/zoom + v·y'/zoom",
                "= (-10|1|20)", "R = dir, as the scene file gives it = (0|0|-1)");
        assertThat(text).contains("a = R·R = 1   (equation 3.6)", "b = 2·R·(O − M) = -42   (equation 3.7)",
                "c = (O − M)·(O − M) − r² = 655   (equation 3.8)", "discriminant b² − 4ac = -856 < 0");
        assertThat(text).contains("b = 2·R·(O − M) = -30", "c = (O − M)·(O − M) − r² = 200",
                "discriminant b² − 4ac = 100 ≥ 0, √ = 10", "t = (−b − √)/2a = 10 ≥ 0: a hit");
        assertThat(text).contains("#2: P = (-10|1|10), |P − O| = 10 < ∞: the nearest so far", "nearest: #2 sphere",
                "#2 sphere, colour (255|0|0)", "pixel colour: 255 0 0");
        assertThat(text.indexOf("1. Ray generation")).isLessThan(text.indexOf("2. Intersection"));
        assertThat(text.indexOf("2. Intersection")).isLessThan(text.indexOf("3. Depth test"));
        assertThat(text.indexOf("3. Depth test")).isLessThan(text.indexOf("4. Result"));
    }

    @Test
    void aRayFromInsideASphereHitsTheFarRootAndASphereBehindHasBothRootsBehind() {
        List<IGeometry> spheres = List.of(new Sphere(new Vector3f(0, 0, 0), 5, new Color(1, 2, 3)),
                new Sphere(new Vector3f(0, 0, 30), 1, new Color(4, 5, 6)));
        Scene scene = new Scene(Color.BLACK, new OrthographicCamera(new Vector3f(0, 0, 0), new Vector3f(0, 0, -1), 1), spheres);
        String text = PixelExplanation.of(scene, 2, 2, 4, 4);
        assertThat(text).contains("< 0, behind O; t = (−b + √)/2a = 5 ≥ 0: O is inside", "both roots behind O, no hit",
                "pixel colour: 1 2 3");
    }

    @Test
    void aPixelThatHitsNothingTakesTheAmbientColour() {
        String text = PixelExplanation.of(Scenes.example("input_rtd"), 0, 0, 1920, 1080);
        assertThat(text).contains("no object is hit", "the scene's ambient colour (127|255|255)", "pixel colour: 127 255 255");
    }

    @Test
    void inAThousandSpheresItSpellsOutTheFirstTwentyAndEveryHitAndCountsTheOtherMisses() {
        Scene scene = Scenes.example("thousand_spheres");
        String text = PixelExplanation.of(scene, 240, 135, 480, 270);
        assertThat(text).contains("… and 977 more objects after #20 that the ray misses", "nearest: #496 sphere");
        for (int i = 1; i <= PixelExplanation.LISTED; i++) {
            assertThat(text).contains("\n   #" + i + " ");
        }
        assertThat(text).contains("#496 sphere").doesNotContain("#21 ");
        assertThat(text.lines().count()).isLessThan(200); // every test spelt out: some 6,000 lines
    }

    @ParameterizedTest(name = "random flat scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void randomPixelsOfRandomFlatScenesAgreeWithThePictureAndTheLoopsHit(long seed) {
        Scene spheres = RandomScenes.generate(seed, 40);
        Scene mixed = MixedScenes.generate(seed, 40);
        for (Scene scene : List.of(spheres, mixed)) {
            FlatShader flat = new FlatShader(scene);
            int[] picture = ParallelRenderer.render(scene.camera(), Bvh.build(scene)::newTracer, tracer -> flat, 80, 60, 2,
                    new RenderProgress()).image().rgb();
            checkRandomPixels(scene, picture, seed);
        }
    }

    @ParameterizedTest(name = "random shaded scene {0}")
    @ValueSource(longs = {11, 12, 13, 14})
    void randomPixelsOfRandomShadedScenesAgreeWithThePictureAndTheLoopsHit(long seed) {
        Scene scene = MixedScenes.shaded(MixedScenes.generate(seed, 40), seed);
        int[] picture = ParallelRenderer.render(scene.camera(), Bvh.build(scene)::newTracer,
                tracer -> new WhittedShader(scene, tracer), 80, 60, 2, new RenderProgress()).image().rgb();
        checkRandomPixels(scene, picture, seed);
    }

    private static void checkRandomPixels(Scene scene, int[] picture, long seed) {
        Random random = new Random(seed);
        for (int k = 0; k < 40; k++) {
            int x = random.nextInt(80);
            int y = random.nextInt(60);
            String text = PixelExplanation.of(scene, x, y, 80, 60);
            Matcher colour = COLOUR.matcher(text);
            assertThat(colour.find()).as(text).isTrue();
            int rgb = Integer.parseInt(colour.group(1)) << 16 | Integer.parseInt(colour.group(2)) << 8
                    | Integer.parseInt(colour.group(3));
            assertThat(rgb).as("pixel (%d, %d)%n%s", x, y, text).isEqualTo(picture[y * 80 + x]);
            Hit hit = scene.nearestHit(scene.camera().generateRay(x, y, 80, 60));
            Matcher nearest = NEAREST.matcher(text);
            assertThat(nearest.find()).isTrue();
            assertThat(nearest.group(2) == null ? -1 : Integer.parseInt(nearest.group(2)) - 1)
                    .isEqualTo(hit == null ? -1 : hit.index());
            assertThat(text).doesNotContain("please report");
        }
    }

    @Test
    void withLightsItShowsEachLightsTermsTheShadowRayAndTheBouncesAsATree() {
        Scene scene = MixedScenes.shaded(MixedScenes.generate(3, 40), 3);
        String text = null;
        for (int y = 0; y < 60 && text == null; y++) {
            for (int x = 0; x < 80; x++) {
                String candidate = PixelExplanation.of(scene, x, y, 80, 60);
                if (candidate.contains("from over (× reflective")) {
                    text = candidate;
                    break;
                }
            }
        }
        assertThat(text).isNotNull().contains("4. Result, shaded", "light 1 at", "shadow ray from over along",
                "ambient  = ambient·c⊙I = ", "diffuse  = diffuse·c⊙I·(N·L) = ", "specular = specular·I·(Rl·E)^shininess = ",
                "5 bounces left", "4 bounces left", "colour = surface + reflective·reflection");
        int camera = indentOf(text, "5 bounces left");
        assertThat(indentOf(text, "4 bounces left")).isGreaterThan(camera);
    }

    /**
     * A ray along the axis of a glass ball that also mirrors, onto a plane seen from its back:
     * Snell's numbers face on (n = 1/1.5, cos θi = 1, sin²θt = 0, cos θt = 1), the plane's normal
     * turned round as a back's is, and Schlick's sum in words and numbers, as the shader adds it.
     */
    @Test
    void glassThatMirrorsShowsSnellsNumbersAndSchlicksSumAndAPlanesBack() {
        List<IGeometry> objects = List.of(
                new Sphere(Vector3f.ZERO, 1, new Color(255, 255, 255), new Material(0.1f, 0.5f, 0.5f, 100, 0.5f, 0.9f, 1.5f)),
                new Plane(new Vector3f(0, 0, 5), new Vector3f(0, 0, 1), new Color(200, 0, 0), Material.DEFAULT));
        Scene scene = new Scene(Color.BLACK, new OrthographicCamera(new Vector3f(0, 0, -5), new Vector3f(0, 0, 1), 1),
                objects, List.of(new Light(new Vector3f(0, 0, -10), new Rgb(1, 1, 1))));
        String text = PixelExplanation.of(scene, 1, 1, 2, 2); // x' = y' = 0: the ray along the axis, P = (0|0|-1) exactly
        assertThat(text).contains(
                "n = n1/n2 = 1/1.5, cos θi = E·N = 1, sin²θt = n²(1 − cos²θi) = 0, cos θt = √(1 − sin²θt) = 1",
                "from under = P − ε·N = (0|0|-0.9998)",
                "(the ray meets its back: N turned round)",
                "Fresnel (Schlick): reflectance R = 0.04",
                "colour = surface + reflective·reflection·R + transparency·refraction·(1 − R) = ");
    }

    /** A smooth triangle's normal, checkable by hand: its corners' normals and P's weights, here (½, ¼, ¼). */
    @Test
    void aSmoothTrianglesNormalShowsTheCornerNormalsAndTheWeightsItBlends() {
        Triangle smooth = new Triangle(new Vector3f(0, 0, 0), new Vector3f(1, 0, 0), new Vector3f(0, 1, 0),
                new Vector3f[] {new Vector3f(0, 0, 1), new Vector3f(1, 0, 1), new Vector3f(0, 1, 1)}, new Color(50, 90, 190),
                Material.DEFAULT);
        Scene scene = new Scene(Color.BLACK, new OrthographicCamera(new Vector3f(0.25f, 0.25f, 5), new Vector3f(0, 0, -1), 1),
                List.of(smooth), List.of(new Light(new Vector3f(0, 0, 10), new Rgb(1, 1, 1))));
        String text = PixelExplanation.of(scene, 1, 1, 2, 2); // the ray from (0.25|0.25|5) straight down onto P = (0.25|0.25|0)
        assertThat(text).contains("smooth: N = normalize(w1·n1 + w2·n2 + w3·n3), the corners' normals n1 = (0|0|1), "
                + "n2 = (1|0|1), n3 = (0|1|1) by P's weights (the area across from each corner) w = (0.5|0.25|0.25)");
        float length = (float) Math.sqrt(0.25 * 0.25 * 2 + 1); // normalize((0.25|0.25|1))
        assertThat(text).contains("N = " + Numbers.of(new Vector3f(0.25f / length, 0.25f / length, 1 / length)));
    }

    private static int indentOf(String text, String part) {
        int at = text.indexOf(part);
        int lineStart = text.lastIndexOf('\n', at) + 1;
        int indent = 0;
        while (text.charAt(lineStart + indent) == ' ') {
            indent++;
        }
        return indent;
    }

    @Test
    void aCameraLookingStraightDownSaysWhyWorldXIsRight() {
        Scene scene = new Scene(Color.BLACK, new OrthographicCamera(new Vector3f(0, 5, 0), new Vector3f(0, -1, 0), 1),
                List.of(new Sphere(new Vector3f(0, 0, 0), 1, new Color(255, 0, 0), Material.DEFAULT)));
        String text = PixelExplanation.of(scene, 1, 1, 2, 2);
        assertThat(text).contains("u = (1|0|0)   (right in the image: looking straight up or down, dir × (0,1,0) is zero, "
                + "so world x is right, as ImageAxes.of says)").doesNotContain("u = normalize(dir × (0,1,0))");
        String tilted = PixelExplanation.of(new Scene(Color.BLACK, new OrthographicCamera(new Vector3f(0, 5, 0),
                new Vector3f(0, -1, -1), 1), scene.objects()), 1, 1, 2, 2);
        assertThat(tilted).contains("u = normalize(dir × (0,1,0)) = (1|0|0)");
    }
}
