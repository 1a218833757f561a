package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static rtd.accel.Grazing.missesExactly;
import static rtd.accel.Grazing.point;
import static rtd.accel.Grazing.tinySpheres;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Function;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.render.Shader;
import rtd.render.Tracer;
import rtd.scene.Light;
import rtd.scene.Scene;
import rtd.shade.WhittedShader;
import rtd.testing.MixedScenes;

/**
 * The light grids answer a shadow ray's question, "does it hit anything before the light?", as
 * the paper's loop does: for random scenes of every kind of object, lights near and far, and
 * shadow rays from the objects, from among them and from far away; and where rounding lets the
 * test hit beside a tiny sphere.
 */
@DisplayName("The light grids answer shadow rays as the loop does")
class LightGridTest {

    /** The loop's answer: a hit nearer than the light. */
    private static boolean loopBlocked(Scene scene, Ray ray, float distance) {
        Hit hit = scene.nearestHit(ray);
        return hit != null && hit.distance() < distance;
    }

    /** Shadow rays from {@code origins} to each light, checked against the loop; answers how many a grid served. */
    private static int checkShadowRays(Scene scene, LightGrids grids, List<Vector3f> origins) {
        Tracer tracer = grids.newTracer(new LinearTracer(scene));
        int byGrid = 0;
        for (Light light : scene.lights()) {
            for (Vector3f origin : origins) {
                Vector3f toLight = light.position().subtract(origin); // as the shader makes it
                Ray ray = new Ray(origin, toLight);
                float distance = toLight.magnitude() - light.clearance();
                assertThat(tracer.blocked(ray, distance)).as("from " + origin + " to " + light.position())
                        .isEqualTo(loopBlocked(scene, ray, distance));
                float whole = toLight.magnitude(); // a ray that ends at the light itself is answered too
                assertThat(tracer.blocked(ray, whole)).as("from " + origin + " to " + light.position() + ", whole")
                        .isEqualTo(loopBlocked(scene, ray, whole));
                if (grids.grids().stream().anyMatch(grid -> grid.cellOf(ray, distance) >= 0)) {
                    byGrid++;
                }
            }
        }
        return byGrid;
    }

    /** Points on the objects (where random rays hit them), among them, around them and far away. */
    private static List<Vector3f> origins(Scene scene, Random random) {
        List<Vector3f> origins = new ArrayList<>();
        for (int i = 0; i < 1_500; i++) {
            Ray ray = MixedScenes.ray(random, scene);
            Hit hit = scene.nearestHit(ray);
            if (hit != null) {
                origins.add(hit.point());
            }
        }
        for (int i = 0; i < 500; i++) {
            float half = i % 3 == 0 ? 14 : i % 3 == 1 ? 40 : 120;
            origins.add(new Vector3f((random.nextFloat() * 2 - 1) * half, (random.nextFloat() * 2 - 1) * half,
                    (random.nextFloat() * 2 - 1) * half));
        }
        return origins;
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void everyShadowRayGetsTheLoopsAnswer(long seed) {
        Random random = new Random(seed);
        Scene mixed = MixedScenes.generate(seed, 300);
        List<Light> lights = new ArrayList<>();
        for (float distance : new float[] {25, 60, 400}) {
            Vector3f direction = new Vector3f((float) random.nextGaussian(), (float) random.nextGaussian(),
                    (float) random.nextGaussian()).normalize();
            lights.add(new Light(direction.multiply(distance), new Rgb(1, 1, 1)));
        }
        lights.add(new Light(new Vector3f(0.5f, -0.25f, 0), new Rgb(1, 1, 1))); // among the objects: no grid
        Scene scene = new Scene(mixed.ambient(), mixed.camera(), mixed.objects(), lights);
        LightGrids grids = LightGrids.build(scene, 1000, 1000, 1, 2);

        int served = checkShadowRays(scene, grids, origins(scene, random));

        assertThat(grids.count()).isBetween(1, 3);
        assertThat(served).as("shadow rays the grids served").isGreaterThan(1_000);
    }

    @Test
    void shadowRaysFromFarBesideTinySpheresGetTheLoopsAnswerWhereRoundingMakesHitsBesideThem() {
        Random random = new Random(7);
        List<IGeometry> spheres = tinySpheres(random);
        Vector3f light = new Vector3f(0, 80, 0);
        Scene scene = new Scene(new Color(0, 0, 0),
                new PerspectiveCamera(new Vector3f(0, 0, 60), new Vector3f(0, 0, -1), 60), spheres,
                List.of(new Light(light, new Rgb(1, 1, 1))));
        LightGrids grids = LightGrids.build(scene, 2048, 2048, 1, 1); // a fine picture: a pixel is a few radii
        List<Vector3f> origins = new ArrayList<>();
        int besides = 0;
        for (int i = 0; i < 6_000; i++) {
            Sphere target = (Sphere) spheres.get(random.nextInt(spheres.size()));
            // from below the spheres, on the line from the light past the sphere, off by up to 20 radii
            Vector3f away = target.center().subtract(light);
            Vector3f origin = light.add(away.multiply(1.2f + random.nextFloat() * 0.3f))
                    .add(new Vector3f(random.nextFloat() * 2 - 1, 0, random.nextFloat() * 2 - 1)
                            .multiply(target.radius() * 20 * random.nextFloat()));
            origins.add(origin);
            Ray ray = new Ray(origin, light.subtract(origin));
            Hit hit = scene.nearestHit(ray);
            if (hit != null && missesExactly(ray, (Sphere) spheres.get(hit.index()))) {
                besides++;
            }
        }

        int served = checkShadowRays(scene, grids, origins);

        assertThat(besides).as("hits the loop reports beside a sphere").isGreaterThan(0);
        assertThat(served).isGreaterThan(2_000);
    }

    @Test
    void raysThatEndBesideTheLightGetTheLoopsAnswerWithinTheGapFromTheGridAndBeyondItFromTheOthers() {
        // spheres just in front of a light at 0; half the rays end within the gap of it, half 5 mm off
        Random random = new Random(5);
        List<IGeometry> spheres = new ArrayList<>();
        for (int i = 0; i < 300; i++) {
            Vector3f centre = new Vector3f((random.nextFloat() * 2 - 1) * 0.02f, (random.nextFloat() * 2 - 1) * 0.02f,
                    0.03f + random.nextFloat() * 0.02f);
            spheres.add(new Sphere(centre, 0.0005f + random.nextFloat() * 0.003f, new Color(200, 100, 50)));
        }
        Vector3f light = new Vector3f(0, 0, 0);
        Scene scene = new Scene(new Color(0, 0, 0),
                new PerspectiveCamera(new Vector3f(0, 0, 60), new Vector3f(0, 0, -1), 60), spheres,
                List.of(new Light(light, new Rgb(1, 1, 1))));
        LightGrids grids = LightGrids.build(scene, 2048, 2048, 1, 1);
        LightGrids.Grid grid = grids.grids().get(0);
        double gap = grid.footprint().gap();
        Tracer tracer = grids.newTracer(new LinearTracer(scene));
        int served = 0;
        for (int i = 0; i < 20_000; i++) {
            double off = i % 2 == 0 ? gap / 3 : 0.005;
            Vector3f end = new Vector3f((float) (random.nextGaussian() * off), (float) (random.nextGaussian() * off),
                    (float) (random.nextGaussian() * off));
            Vector3f origin = new Vector3f((random.nextFloat() * 2 - 1) * 0.03f, (random.nextFloat() * 2 - 1) * 0.03f,
                    0.06f);
            Ray ray = new Ray(origin, end.subtract(origin));
            float distance = end.subtract(origin).magnitude() - scene.lights().get(0).clearance(); // as the shader's
            assertThat(tracer.blocked(ray, distance)).as("ray " + i + " " + ray)
                    .isEqualTo(loopBlocked(scene, ray, distance));
            served += grid.cellOf(ray, distance) >= 0 ? 1 : 0;
        }
        assertThat(served).isBetween(5_000, 10_000);
    }

    @Test
    void raysThatEndWithinTheGapBesideTheLightAndGrazeABoxsOutlineGetTheLoopsAnswer() {
        // far from 0 the gap (here 0.23) is wide beside the boxes' rounding: a ray that ends beside
        // the light, on the inner side of a box's outline seen from it, comes from a direction just
        // outside that outline, a few pixels off; only the footprint's widening by the angle keeps
        // the box in the ray's cell (8 pixels here, 2,000 small boxes)
        Random random = new Random(11);
        double[] middle = {-53_000, 89_000, 47_000};
        List<IGeometry> boxes = new ArrayList<>();
        for (int i = 0; i < 2_000; i++) {
            Vector3f corner = point(middle[0] + (random.nextDouble() * 2 - 1) * 10,
                    middle[1] + (random.nextDouble() * 2 - 1) * 10, middle[2] + (random.nextDouble() * 2 - 1) * 10);
            boxes.add(Box.between(corner, corner.add(new Vector3f(0.01f + random.nextFloat() * 0.5f,
                    0.01f + random.nextFloat() * 0.5f, 0.01f + random.nextFloat() * 0.5f)), new Color(200, 100, 50),
                    Material.DEFAULT));
        }
        double[] x = {middle[0] + 3, middle[1] + 30, middle[2] - 2};
        Vector3f light = point(x[0], x[1], x[2]);
        Scene scene = new Scene(new Color(0, 0, 0),
                new PerspectiveCamera(point(middle[0], middle[1], middle[2] + 60), new Vector3f(0, 0, -1), 60), boxes,
                List.of(new Light(light, new Rgb(1, 1, 1))));
        LightGrids grids = LightGrids.build(scene, 2048, 2048, 1, 1);
        LightGrids.Grid grid = grids.grids().get(0);
        Tracer tracer = grids.newTracer(new LinearTracer(scene));
        int served = 0;
        int blocked = 0;
        for (int i = 0; i < 20_000; i++) {
            float[] box = new float[6];
            KnownShapes.putBox(boxes.get(random.nextInt(boxes.size())), box, 0);
            Grazing grazing = Grazing.of(box, x, random); // Q just inside the box's outline seen from the light
            double[] q = grazing.q();
            // the end, up to the gap off the light towards the inside; the origin beyond Q on the line
            double[] end = grazing.awayFromSide();
            double off = grid.footprint().gap() * (0.3 + 0.69 * random.nextDouble());
            double beyond = Math.pow(10, -1 + 2 * random.nextDouble());
            Vector3f origin = point(x[0] + q[0] + beyond * (q[0] - off * end[0]),
                    x[1] + q[1] + beyond * (q[1] - off * end[1]), x[2] + q[2] + beyond * (q[2] - off * end[2]));
            Vector3f toEnd = point(x[0] + off * end[0], x[1] + off * end[1], x[2] + off * end[2]).subtract(origin);
            Ray ray = new Ray(origin, toEnd);
            float distance = toEnd.magnitude() - scene.lights().get(0).clearance(); // as the shader's

            boolean loop = loopBlocked(scene, ray, distance);
            assertThat(tracer.blocked(ray, distance)).as("ray " + i + " " + ray).isEqualTo(loop);
            if (grid.cellOf(ray, distance) >= 0) {
                served++;
                blocked += loop ? 1 : 0;
            }
        }
        assertThat(served).isGreaterThan(5_000);
        assertThat(blocked).as("served rays that hit a box").isGreaterThan(1_000);
    }

    @Test
    void aSphereSeenFromTheLightCoversThePixelsItsTangentsGive() {
        // the point at 0 looks along +z at the box from (−1, −1, 9) to (1, 1, 11): tangents up to
        // 1/9, so 100 pixels span ±1.01/9 and a unit of tangent is 445.54 pixels
        PointFootprint footprint = PointFootprint.around(new Vector3f(0, 0, 0), new float[] {-1, -1, 9, 1, 1, 11}, 100);
        Sphere sphere = new Sphere(new Vector3f(0, 0, 10), 0.5f, new Color(1, 2, 3));
        float[] box = new float[6];
        int[] pixels = new int[4];

        float nearest = footprint.putObject(sphere, box, pixels, 0);

        // its box, 0.501 wide and grown by 3e-5 for rays of up to 4.4 units, ends at tangent
        // ±0.50103/9.49897 = ±0.052746: 50 ∓ 23.500 pixels
        assertThat(pixels).containsExactly(26, 26, 73, 73);
        assertThat(nearest).isCloseTo(9.49897f, within(1e-4f));
        assertThat(footprint.reach()).isCloseTo(1.25 * Math.sqrt(123), within(1e-9));
    }

    @Test
    void aShadowRayIsServedOnlyIfItEndsAtTheLightRunsNoFartherThanTheReachAndComesFromThePicture() {
        PointFootprint footprint = PointFootprint.around(new Vector3f(0, 0, 0), new float[] {-1, -1, 9, 1, 1, 11}, 100);

        // from (0.3, 0, 12): tangent 0.025, pixel 50 + 11.14 across, 50 down
        assertThat(footprint.pixelOf(0.3, 0, 12, 0, 0, 0, 12.004)).isEqualTo(50 * 100 + 61);
        assertThat(footprint.pixelOf(0.3, 0, 12, 1e-3, 0, 0, 12.004)).as("ends beside the light").isEqualTo(-1);
        assertThat(footprint.pixelOf(0.3, 0, 13.9, 0, 0, 0, 13.9)).as("longer than the reach").isEqualTo(-1);
        assertThat(footprint.pixelOf(0, 0, -5, 0, 0, 0, 5)).as("from behind the light").isEqualTo(-1);
        assertThat(footprint.pixelOf(5, 0, 10, 0, 0, 0, 11.18)).as("from beside the picture").isEqualTo(-1);
    }

    @Test
    void aFarLightServesRaysFromAtMostADiagonalBeyondTheBoxAndAFarFarLightGetsNoGrid() {
        float[] box = {-1, -1, 9, 1, 1, 11};
        // 1,000 units away the farthest corner is 1,011.00 away, and 1.25 times that would grow
        // every object by its rounding over 250 units; a diagonal of the box, √12, is the room
        PointFootprint far = PointFootprint.around(new Vector3f(0, 0, -990), box, 100);
        double farthest = Math.sqrt(1 + 1 + 1001.0 * 1001.0);

        assertThat(far.reach()).isCloseTo(farthest + Math.sqrt(12), within(1e-9));
        // 1e7 away the gap, 2e-6 of 2e7, is 40 units: more than the box's picture is wide
        assertThat(PointFootprint.around(new Vector3f(0, 0, -1e7f), box, 100)).isNull();
    }

    @Test
    void theLightsBeyondWhatTheGridsMayHoldLeaveTheirShadowRaysToTheTree() {
        Scene mixed = MixedScenes.generate(4, 100);
        List<Light> lights = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            lights.add(new Light(new Vector3f(10 * i, 200, 0), new Rgb(1, 1, 1)));
        }
        Scene scene = new Scene(mixed.ambient(), mixed.camera(), mixed.objects().subList(0, 100), lights);

        assertThat(LightGrids.build(scene, 40, 30, 1, 1, 350).count()).as("350 copies of 100 objects").isEqualTo(3);
        assertThat(LightGrids.build(scene, 40, 30, 1, 1, 10).count()).as("always one").isEqualTo(1);
        assertThat(LightGrids.build(scene, 40, 30, 1, 1).count()).isEqualTo(5);
    }

    @Test
    void aLightAmongTheObjectsOrWithNothingToShadowGetsNoGrid() {
        Scene mixed = MixedScenes.generate(3, 100);
        Light among = new Light(new Vector3f(0, 0, 0), new Rgb(1, 1, 1));
        Light outside = new Light(new Vector3f(0, 200, 0), new Rgb(1, 1, 1));

        assertThat(LightGrids.build(new Scene(mixed.ambient(), mixed.camera(), mixed.objects(), List.of(among, outside)),
                40, 30, 1, 1).count()).isEqualTo(1);
        assertThat(LightGrids.build(new Scene(mixed.ambient(), mixed.camera(), List.of(), List.of(outside)), 40, 30, 1,
                1).count()).isZero();
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {31, 32, 33})
    void aShadedPictureWithTheLightGridsIsTheBvhsPixelForPixel(long seed) {
        Scene mixed = MixedScenes.shaded(MixedScenes.generate(seed, 250), seed);
        List<Light> lights = new ArrayList<>(mixed.lights());
        lights.add(new Light(new Vector3f(10, 80, 30), new Rgb(0.5f, 0.5f, 0.5f))); // one with a grid, surely
        Scene scene = new Scene(mixed.ambient(), mixed.camera(), mixed.objects(), lights);
        Bvh bvh = Bvh.build(scene);
        LightGrids grids = LightGrids.build(scene, 80, 60, 1, 2);
        Function<Tracer, Shader> shaders = tracer -> new WhittedShader(scene, tracer);

        RenderResult withGrids = ParallelRenderer.render(scene.camera(), () -> grids.newTracer(bvh.newTracer()),
                shaders, 80, 60, 2, new RenderProgress());
        RenderResult tree = ParallelRenderer.render(scene.camera(), bvh::newTracer, shaders, 80, 60, 2,
                new RenderProgress());

        assertThat(grids.count()).isPositive();
        assertThat(withGrids.image().rgb()).isEqualTo(tree.image().rgb());
        assertThat(withGrids.work().secondaryRays()).isEqualTo(tree.work().secondaryRays());
        assertThat(withGrids.work().rays()).isEqualTo(tree.work().rays());
    }

    @Test
    void theGridsAreTheSameForOneAndTwoThreads() {
        Scene mixed = MixedScenes.generate(9, 30_000);
        Scene scene = new Scene(mixed.ambient(), mixed.camera(), mixed.objects(),
                List.of(new Light(new Vector3f(50, 60, 70), new Rgb(1, 1, 1))));
        LightGrids one = LightGrids.build(scene, 200, 100, 1, 1);
        LightGrids two = LightGrids.build(scene, 200, 100, 1, 2);
        assertThat(two.entries()).isEqualTo(one.entries()).isGreaterThan(30_000);
        assertThat(two.grids().get(0).cells().places).isEqualTo(one.grids().get(0).cells().places);
    }
}
