package rtd.shade;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.accel.Bvh;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.scene.Light;
import rtd.scene.Scene;

/** Shadows, reflection and refraction, against numbers worked out by hand or known from The Ray Tracer Challenge. */
@DisplayName("Whitted shading")
class WhittedShaderTest {

    private static final Material OUTER = new Material(0.1f, 0.7f, 0.2f, 200, 0, 0, 1);
    private static final Material GLASS = new Material(0.1f, 0.9f, 0.9f, 200, 0, 1, 1.5f);
    private static final float HALF_ROOT_2 = (float) Math.sqrt(2) / 2;

    /** The book's default world: two spheres at the origin and a white light up left in front. */
    private static List<IGeometry> defaultObjects() {
        List<IGeometry> objects = new ArrayList<>();
        objects.add(new Sphere(Vector3f.ZERO, 1, new Color(204, 255, 153), OUTER)); // (0.8, 1.0, 0.6)
        objects.add(new Sphere(Vector3f.ZERO, 0.5f, Color.fromRGB(0xFFFFFF), Material.DEFAULT));
        return objects;
    }

    private static Scene world(List<IGeometry> objects) {
        return new Scene(Color.BLACK, new PerspectiveCamera(new Vector3f(0, 0, -5), new Vector3f(0, 0, 1), 60), objects,
                List.of(new Light(new Vector3f(-10, 10, -10), new Rgb(1, 1, 1))));
    }

    private static WhittedShader shader(Scene scene) {
        return new WhittedShader(scene, new LinearTracer(scene));
    }

    private static void assertColour(Rgb actual, double r, double g, double b, double tolerance) {
        assertThat(actual.red()).isCloseTo((float) r, within((float) tolerance));
        assertThat(actual.green()).isCloseTo((float) g, within((float) tolerance));
        assertThat(actual.blue()).isCloseTo((float) b, within((float) tolerance));
    }

    @Test
    void theCheckValueOfTheTwoSphereWorldIsPixel97_121_73() {
        Scene scene = world(defaultObjects());
        Rgb colour = shader(scene).colourAt(new Ray(new Vector3f(0, 0, -5), new Vector3f(0, 0, 1)), WhittedShader.BOUNCES);
        assertColour(colour, 0.38066, 0.47583, 0.2855, 1e-4);
        assertThat(colour.toColor()).isEqualTo(new Color(97, 121, 73));
        // and through the BVH, the same to the last bit
        Rgb viaBvh = new WhittedShader(scene, Bvh.build(scene).newTracer())
                .colourAt(new Ray(new Vector3f(0, 0, -5), new Vector3f(0, 0, 1)), WhittedShader.BOUNCES);
        assertThat(viaBvh).isEqualTo(colour);
    }

    @Test
    void aRayThatHitsNothingSeesTheBackground() {
        Scene scene = new Scene(new Color(255, 0, 0), world(defaultObjects()).camera(), defaultObjects(),
                world(defaultObjects()).lights());
        assertThat(shader(scene).colourAt(new Ray(new Vector3f(0, 0, -5), new Vector3f(0, 1, 0)), 5))
                .isEqualTo(new Rgb(1, 0, 0));
    }

    @Test
    void aPointBehindAnObjectFromTheLightIsInShadowAndOneBeforeItIsNot() {
        WhittedShader shader = shader(world(defaultObjects()));
        Light light = new Light(new Vector3f(-10, 10, -10), new Rgb(1, 1, 1));
        assertThat(shader.isShadowed(new Vector3f(10, -10, 10), light)).isTrue();
        assertThat(shader.isShadowed(new Vector3f(0, 10, 0), light)).as("nothing on the line").isFalse();
        assertThat(shader.isShadowed(new Vector3f(-20, 20, -20), light)).as("behind the light").isFalse();
        assertThat(shader.isShadowed(new Vector3f(-2, 2, -2), light)).as("between light and object").isFalse();
    }

    /**
     * A lamp on a ball: a light on top of a sphere of radius 1.5 lights a ceiling above it. Each
     * point's shadow ray ends at the light, where it meets the sphere; without the light's
     * clearance (1e-4 · (1 + 1.5) = 2.5e-4) the rounding of that hit shadowed 73 of these 400
     * points at random. A point straight below the ball stays in its shadow.
     */
    @Test
    void aLightOnASurfaceLightsWhatItFacesAndShadowsWhatTheSurfaceHides() {
        List<IGeometry> objects = List.of(new Sphere(Vector3f.ZERO, 1.5f, new Color(220, 60, 60), Material.DEFAULT));
        Light lamp = new Light(new Vector3f(0, 1.5f, 0), new Rgb(1, 1, 1));
        assertThat(lamp.clearance()).isEqualTo(1e-4f * 2.5f);
        Scene scene = new Scene(Color.BLACK, world(objects).camera(), objects, List.of(lamp));
        for (WhittedShader shader : List.of(shader(scene), new WhittedShader(scene, Bvh.build(scene).newTracer()))) {
            int shadowed = 0;
            for (int i = 0; i < 400; i++) {
                Vector3f ceiling = new Vector3f(-2 + (i % 20) * 0.2113f, 4, -2 + (i / 20) * 0.1979f);
                shadowed += shader.isShadowed(ceiling, lamp) ? 1 : 0;
            }
            assertThat(shadowed).as("ceiling points in shadow").isZero();
            assertThat(shader.isShadowed(new Vector3f(0.1f, -4, 0.2f), lamp)).as("below the ball").isTrue();
        }
    }

    @Test
    void aMirrorFloorReflectsTheSpheresAtHalfStrength() {
        List<IGeometry> objects = defaultObjects();
        objects.add(new Plane(new Vector3f(0, -1, 0), new Vector3f(0, 1, 0), Color.fromRGB(0xFFFFFF),
                new Material(0.1f, 0.9f, 0.9f, 200, 0.5f, 0, 1)));
        WhittedShader shader = shader(world(objects));
        Ray ray = new Ray(new Vector3f(0, 0, -3), new Vector3f(0, -HALF_ROOT_2, HALF_ROOT_2));
        // The book's shade_hit with a reflective material: its ε is 1e-4 where ours grows with |P|.
        assertColour(shader.colourAt(ray, 5), 0.87677, 0.92436, 0.82918, 2e-3);
        // With no bounce left the mirror shows nothing: only the floor's own light.
        Rgb matt = shader.colourAt(ray, 0);
        assertThat(matt.red()).isLessThan(0.87677f - 0.1f);
    }

    @Test
    void aRayAlongADiameterOfAGlassSphereGoesStraightThrough() {
        // A glass sphere with nothing behind it but a red wall: the ray leaves along the same line.
        List<IGeometry> objects = new ArrayList<>();
        objects.add(new Sphere(Vector3f.ZERO, 1, Color.fromRGB(0xFFFFFF), new Material(0, 0, 0, 200, 0, 1, 1.5f)));
        objects.add(new Plane(new Vector3f(0, 0, 5), new Vector3f(0, 0, -1), new Color(255, 0, 0),
                new Material(1, 0, 0, 200, 0, 0, 1)));
        Scene scene = new Scene(Color.BLACK, world(objects).camera(), objects,
                List.of(new Light(new Vector3f(0, 0, -10), new Rgb(1, 1, 1))));
        Rgb seen = shader(scene).colourAt(new Ray(new Vector3f(0, 0, -5), new Vector3f(0, 0, 1)), 5);
        assertColour(seen, 1, 0, 0, 1e-4); // the wall's ambient 1 · red, through two refractions
        Rgb aside = shader(scene).colourAt(new Ray(new Vector3f(0, 3, -5), new Vector3f(0, 0, 1)), 5);
        assertColour(aside, 1, 0, 0, 1e-4);
    }

    @Test
    void pastTheCriticalAngleNoLightComesThrough() {
        Scene scene = world(List.of(new Sphere(Vector3f.ZERO, 1, Color.fromRGB(0xFFFFFF), GLASS)));
        // Inside the glass at height √2/2, looking straight up: 45° against the normal, past glass's 41.8°.
        Surface surface = Surface.at(new Ray(new Vector3f(0, 0, HALF_ROOT_2), new Vector3f(0, 1, 0)),
                scene.nearestHit(new Ray(new Vector3f(0, 0, HALF_ROOT_2), new Vector3f(0, 1, 0))));
        assertThat(surface.inside()).isTrue();
        assertThat(Snell.at(surface).totalInternalReflection()).isTrue();
        assertThat(Snell.at(surface).reflectance()).isEqualTo(1f);
    }

    @Test
    void schlicksReflectanceIsSmallFaceOnAndGrowsTowardsGrazing() {
        Scene scene = world(List.of(new Sphere(Vector3f.ZERO, 1, Color.fromRGB(0xFFFFFF), GLASS)));
        Ray faceOn = new Ray(new Vector3f(0, 0, -5), new Vector3f(0, 0, 1));
        assertThat(Snell.at(Surface.at(faceOn, scene.nearestHit(faceOn))).reflectance())
                .isCloseTo(0.04f, within(1e-5f));
        Ray grazing = new Ray(new Vector3f(0, 0.99f, -2), new Vector3f(0, 0, 1));
        assertThat(Snell.at(Surface.at(grazing, scene.nearestHit(grazing))).reflectance())
                .isCloseTo(0.48873f, within(1e-4f));
    }

    /**
     * Rays from the centre of a sphere of ior 100,000 leave it face on: cos θi = E·N is 1, or by
     * rounding a hair above it, which n² = 10¹⁰ would blow up into sin²θt ≪ 0, cos θt ≫ 1 and a
     * reflectance far below 0 (it was −58,495 in one such pixel).
     */
    @Test
    void aHugeIorLeavingFaceOnKeepsTheAnglesRealAndTheReflectanceBetween0And1() {
        Material diamondAndMore = new Material(0.1f, 0.9f, 0.9f, 200, 0.5f, 1, 1e5f);
        Scene scene = world(List.of(new Sphere(new Vector3f(0.3f, -0.7f, 0.2f), 1.3f, Color.fromRGB(0xFFFFFF), diamondAndMore)));
        java.util.Random random = new java.util.Random(3);
        for (int i = 0; i < 500; i++) {
            Ray out = new Ray(new Vector3f(0.3f, -0.7f, 0.2f),
                    new Vector3f((float) random.nextGaussian(), (float) random.nextGaussian(), (float) random.nextGaussian()));
            Surface surface = Surface.at(out, scene.nearestHit(out));
            Snell snell = Snell.at(surface);
            assertThat(snell.sin2Transmitted()).as("sin²θt of ray " + i).isGreaterThanOrEqualTo(0f);
            if (!snell.totalInternalReflection()) { // n² · 2.4e-7 is past the critical angle already: most are
                assertThat(snell.cosTransmitted()).as("cos θt of ray " + i).isBetween(0f, 1f);
            }
            assertThat(Snell.at(surface).reflectance()).as("reflectance of ray " + i).isBetween(0f, 1f);
        }
    }

    @Test
    void theOverPointLiesAboveTheSurfaceAndTheUnderPointBelowIt() {
        Scene scene = world(defaultObjects());
        Ray ray = new Ray(new Vector3f(0, 0, -5), new Vector3f(0, 0, 1));
        Surface surface = Surface.at(ray, scene.nearestHit(ray));
        assertThat(surface.over().z()).isLessThan(-1f).isGreaterThan(-1.001f);
        assertThat(surface.under().z()).isGreaterThan(-1f).isLessThan(-0.999f);
        assertThat(surface.normal()).isEqualTo(new Vector3f(0, 0, -1));
    }

    /**
     * A yellow box's front face under a white light, seen by an orthographic camera whose ray at
     * x = 0 runs exactly along the box's left face: it hits the front face on the edge and is lit
     * as the front face beside it (234 234 59), not darkened as if it hit the left face, which
     * faces away from the light (55 55 14 was the seam).
     */
    @Test
    void aRayAlongABoxFaceIsLitAsTheFaceItHitsOnTheEdge() {
        Box box = Box.between(new Vector3f(0, -1, -1), new Vector3f(2, 1, 0), new Color(240, 240, 60), Material.DEFAULT);
        Scene scene = new Scene(new Color(30, 30, 40), new OrthographicCamera(new Vector3f(0, 0, 10),
                new Vector3f(0, 0, -1), 50), List.of(box), List.of(new Light(new Vector3f(-3, 4, 20), new Rgb(1, 1, 1))));
        WhittedShader shader = shader(scene);
        Rgb onTheEdge = shader.colourAt(new Ray(new Vector3f(0, 0, 10), new Vector3f(0, 0, -1)), WhittedShader.BOUNCES);
        Rgb besideIt = shader.colourAt(new Ray(new Vector3f(0.02f, 0, 10), new Vector3f(0, 0, -1)), WhittedShader.BOUNCES);
        assertThat(onTheEdge.toColor()).isEqualTo(new Color(234, 234, 59)).isEqualTo(besideIt.toColor());
    }
}
