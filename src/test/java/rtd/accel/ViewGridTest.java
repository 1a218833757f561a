package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;
import static rtd.accel.SameHit.assertSame;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.scene.Scene;
import rtd.testing.MixedScenes;

/**
 * The view grid's answer to "what does this camera ray hit?" is the paper's loop's, bit for bit:
 * for random scenes of every kind of object seen by random cameras of both kinds, through the
 * pixels' corners and through samples, and where rounding lets the test hit far beside a sphere.
 */
@DisplayName("The view grid finds the loop's hit")
class ViewGridTest {

    private static final int WIDTH = 72;
    private static final int HEIGHT = 40;


    /**
     * Traces every pixel's ray through {@code (x + offset, y + offset)} as the renderer does, in
     * squares of 8 × 8, asks first whether a whole square misses, and checks each against the
     * loop; answers the hits.
     */
    private static List<Hit> checkEveryPixel(Scene scene, ViewGrid grid, int samples, float offset) {
        ViewGridTracer tracer = grid.newTracer();
        RayBundle bundle = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        List<Hit> found = new ArrayList<>();
        for (int top = 0; top < HEIGHT; top += 8) {
            for (int left = 0; left < WIDTH; left += 8) {
                int right = Math.min(WIDTH, left + 8);
                int bottom = Math.min(HEIGHT, top + 8);
                bundle.fill(scene.camera(), left, top, right, bottom, WIDTH, HEIGHT, offset, offset);
                boolean allMiss = tracer.traceAtOnce(bundle, hits);
                if (!allMiss) {
                    tracer.traceAll(bundle, hits);
                }
                for (int i = 0; i < bundle.count(); i++) {
                    Ray ray = bundle.ray(i);
                    Hit expected = scene.nearestHit(ray);
                    String what = "samples " + samples + ", pixel (" + (left + i % (right - left)) + ", "
                            + (top + i / (right - left)) + ") " + ray;
                    assertSame(allMiss ? null : hits.hit(i, bundle, scene.objects()), expected, what);
                    if (expected != null) {
                        found.add(expected);
                    }
                }
            }
        }
        return found;
    }

    /** A camera whose rays are too long for a triangle's narrower rounding gets the wider one. */
    @Test
    void aCameraWhoseRaysAreTooLongForTheTrianglesNarrowerRoundingGetsTheWiderOne() {
        Scene scene = raysTooLongForANarrowerRounding();

        List<Hit> hits = checkEveryPixel(scene, ViewGrid.build(scene, WIDTH, HEIGHT, 1, 1), 1, 0);

        assertThat(hits).as("the loop's hits").hasSizeGreaterThan(WIDTH * HEIGHT / 4);
    }

    static ICamera randomCamera(Random random) {
        Vector3f direction = switch (random.nextInt(4)) {
            case 0 -> new Vector3f(0, 0, -1); // the paper's
            case 1 -> new Vector3f(0, -1, 0); // straight down: the image axes' special case
            default -> new Vector3f(random.nextFloat() * 2 - 1, random.nextFloat() * 2 - 1, random.nextFloat() * 2 - 1);
        };
        float distance = random.nextBoolean() ? 5 : 60; // inside the scene, or outside
        Vector3f position = direction.normalize().multiply(-distance)
                .add(new Vector3f(random.nextFloat() - 0.5f, random.nextFloat() - 0.5f, random.nextFloat() - 0.5f));
        if (random.nextBoolean()) {
            return new PerspectiveCamera(position, direction.multiply(0.5f + random.nextFloat() * 2),
                    5 + random.nextFloat() * 150);
        }
        return new OrthographicCamera(position, direction.multiply(0.5f + random.nextFloat() * 2),
                2 + random.nextFloat() * 6);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 4, 7, 10, 13, 16})
    void forEveryPixelOfRandomScenesSeenByRandomCamerasOfBothKinds(long seed) {
        Scene mixed = MixedScenes.generate(seed, 100 + (int) (seed * 89 % 300));
        Random random = new Random(seed);
        int hits = 0;
        for (int view = 0; view < 4; view++) {
            Scene scene = new Scene(mixed.ambient(), randomCamera(random), mixed.objects());
            for (int samples = 1; samples <= 3; samples++) {
                ViewGrid grid = ViewGrid.build(scene, WIDTH, HEIGHT, samples, 1);
                float offset = samples == 1 ? 0 : (samples - 0.5f) / samples; // the last sample of a pixel
                hits += checkEveryPixel(scene, grid, samples, offset).size();
                if (samples > 1) {
                    hits += checkEveryPixel(scene, grid, samples, 0.5f / samples).size(); // and the first
                }
            }
        }
        assertThat(hits).as("rays that hit something").isGreaterThan(10_000);
    }

    @Test
    void evenWhereRoundingLetsTheTestHitFarBesideSmallSpheresSeenFromAfarThroughAPerspectiveCamera() {
        Vector3f direction = new Vector3f(-0.2f, 0.1f, -1);
        assertFindsHitsBesideSmallSpheres(new PerspectiveCamera(direction.normalize().multiply(-3000), direction, 0.03f), 9);
    }

    @Test
    void aSpheresPictureThroughThePerspectiveCameraIsTheRectangleOfItsGrownBoxsCorners() {
        // Eye at z = 20 looking down −z, 90° across 200 × 100 pixels: f = 100. The sphere at the
        // origin, radius 1, has the box ±1.002; its near corners at depth 18.998 show at
        // x' = ±100 · 1.002 / 18.998 = ±5.274, widened by 0.016 (rounding of the rays), so
        // x = 100 ± 5.29: pixels 95 to 105, and y = 50 ± 5.29: 45 to 55. The box's near face is
        // 18.998 from the eye, less √3 growths at 21.1 units (0.0005).
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 90);
        PerspectiveFootprint footprint = new PerspectiveFootprint(camera, 200, 100, 0);
        int[] pixels = {-7, -7, -7, -7};
        Sphere sphere = new Sphere(new Vector3f(0, 0, 0), 1, new Color(1, 2, 3));
        float[] box = new float[6];
        KnownShapes.putBox(sphere, box, 0);
        float nearest = footprint.put(box, 0, KnownShapes.rounding(sphere).linear(), KnownShapes.rounding(sphere).quadratic(), pixels, 0);
        assertThat(pixels).containsExactly(95, 45, 105, 55);
        assertThat(nearest).isCloseTo(18.9975f, org.assertj.core.data.Offset.offset(0.0001f));

        // A box whose picture ends a thousandth of a pixel short of pixel 105's ray (x' = 100 ·
        // 0.9998 / 20 = 4.999): the rays' rounding could reach it, so the pixel is kept.
        float[] edge = {0, -1, -1, 0.9998f, 1, 0};
        footprint.put(edge, 0, 0, 0, pixels, 0);
        assertThat(pixels[2]).isEqualTo(105);

        // Beside the eye and half behind it: its points in front show at x' ≥ 100 · 1.998 / 1.002
        // = 199.4, beyond the picture's right edge (x' ≤ 100): no pixel.
        KnownShapes.putBox(new Sphere(new Vector3f(3, 0, 20), 1, new Color(1, 2, 3)), box, 0);
        assertThat(footprint.put(box, 0, 0, 0, pixels, 0)).isNaN();
        // Around the eye: every pixel, from distance 0.
        KnownShapes.putBox(new Sphere(new Vector3f(0.5f, 0, 20), 1, new Color(1, 2, 3)), box, 0);
        assertThat(footprint.put(box, 0, 0, 0, pixels, 0)).isLessThanOrEqualTo(0);
        assertThat(pixels).containsExactly(0, 0, 199, 99);
        // Wholly behind the eye: no pixel.
        KnownShapes.putBox(new Sphere(new Vector3f(0, 0, 25), 1, new Color(1, 2, 3)), box, 0);
        assertThat(footprint.put(box, 0, 0, 0, pixels, 0)).isNaN();
    }

    @Test
    void evenWhereRoundingLetsTheTestHitFarBesideSmallSpheresSeenFromAfar() {
        Vector3f direction = new Vector3f(0.3f, -0.2f, -1);
        assertFindsHitsBesideSmallSpheres(new OrthographicCamera(direction.normalize().multiply(-2000), direction, 60), 7);
    }

    /**
     * From thousands of units away a sphere's test rounds its discriminant by more than a small
     * sphere's r²: the paper's loop reports hits well outside the sphere, which the grid must
     * find as well, not only the sphere's outline. Sixty small spheres around the origin, seen
     * by {@code camera}: every pixel as the loop's, and more than 20 hits farther than 1.5 r
     * from their sphere's centre, so that the test does meet such hits.
     */
    private static void assertFindsHitsBesideSmallSpheres(ICamera camera, long seed) {
        Scene scene = smallSpheres(camera, seed);
        assertSomeHitsLieBeside(checkEveryPixel(scene, ViewGrid.build(scene, WIDTH, HEIGHT, 1, 1), 1, 0));
    }

    /** 30,000 small spheres, more than a grid builds on one thread, under the paper's camera. */
    static Scene manySmallSpheres() {
        Random random = new Random(3);
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < 30_000; i++) { // above the count built in parallel
            Vector3f centre = new Vector3f(random.nextFloat() * 40 - 20, random.nextFloat() * 20 - 10,
                    random.nextFloat() * 10);
            objects.add(new Sphere(centre, 0.01f + random.nextFloat() * 0.3f, new Color(1, 2, 3)));
        }
        return new Scene(new Color(0, 0, 0),
                new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50), objects);
    }

    /** Sixty small spheres around the origin, seen by {@code camera}. */
    static Scene smallSpheres(ICamera camera, long seed) {
        Random random = new Random(seed);
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            Vector3f centre = new Vector3f(random.nextFloat() - 0.5f, random.nextFloat() - 0.5f, random.nextFloat() - 0.5f);
            objects.add(new Sphere(centre, 0.002f + random.nextFloat() * 0.02f, new Color(i, 2 * i, 3 * i)));
        }
        return new Scene(new Color(0, 0, 0), camera, objects);
    }

    /** More than 20 of the {@code hits} lie farther than 1.5 r from their sphere's centre. */
    static void assertSomeHitsLieBeside(List<Hit> hits) {
        long beside = hits.stream().filter(hit -> {
            Sphere sphere = (Sphere) hit.object();
            return hit.point().subtract(sphere.center()).magnitude() > 1.5 * sphere.radius();
        }).count();
        assertThat(beside).as("hits farther than 1.5 r from the centre, of %d", hits.size()).isGreaterThan(20);
    }

    @Test
    void aSpheresFootprintIsThePixelsOfItsOutlineGrownByTheRoundingOfItsTest() {
        // Camera at z = 20 looking down −z, 50 pixels a unit, 1920 × 1080: u = (1, 0, 0), v = (0, −1, 0).
        // A sphere at (1, 0.5, 0) of radius 0.1 has the box ±0.1002 (Sphere.bounds) and is met
        // 20.1002 units from the plane, 20.139 with the cone: its rounding grows the box by
        // 2e-6 · 20.139 + 5.597e-6 · 20.139² = 0.00231. So x = 960 + 50 · (1 ± 0.10251) runs from
        // 1004.87 to 1015.13 and y = 540 + 50 · (−0.5 ± 0.10251) from 509.87 to 520.13.
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50);
        Sphere sphere = new Sphere(new Vector3f(1, 0.5f, 0), 0.1f, new Color(1, 2, 3));
        float[] box = new float[6];
        KnownShapes.putBox(sphere, box, 0);
        int[] pixels = new int[4];
        float nearest = new OrthographicFootprint(camera, 1920, 1080, 0).put(box, 0, KnownShapes.rounding(sphere).linear(),
                KnownShapes.rounding(sphere).quadratic(), pixels, 0);
        assertThat(pixels).containsExactly(1005, 510, 1015, 520);
        // Its box's near side is 19.8998 from the plane, less √3 growths (0.00400), the origins'
        // error (0.00008) and a millionth for rounding (0.00002): 19.8957.
        assertThat(nearest).isCloseTo(19.8957f, org.assertj.core.data.Offset.offset(0.00002f));
        // Samples up to 5/6 into a pixel: the pixel before each range may send one in.
        new OrthographicFootprint(camera, 1920, 1080, 5 / 6.0).put(box, 0, KnownShapes.rounding(sphere).linear(),
                KnownShapes.rounding(sphere).quadratic(), pixels, 0);
        assertThat(pixels).containsExactly(1005, 510, 1015, 520);
        new OrthographicFootprint(camera, 1920, 1080, 0.99).put(box, 0, KnownShapes.rounding(sphere).linear(),
                KnownShapes.rounding(sphere).quadratic(), pixels, 0);
        assertThat(pixels).containsExactly(1004, 509, 1015, 520);
    }

    @Test
    void anObjectBehindTheCameraOrBesideThePictureHasNoFootprint() {
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50);
        int[] pixels = {-7, -7, -7, -7};
        float[] behind = new float[6];
        KnownShapes.putBox(new Sphere(new Vector3f(0, 0, 21), 0.5f, new Color(1, 2, 3)), behind, 0);
        float[] beside = new float[6];
        KnownShapes.putBox(new Sphere(new Vector3f(30, 0, 0), 0.5f, new Color(1, 2, 3)), beside, 0);
        ImageFootprint footprint = new OrthographicFootprint(camera, 1920, 1080, 0);
        assertThat(footprint.put(behind, 0, 0, 0, pixels, 0)).isNaN();
        assertThat(footprint.put(beside, 0, 0, 0, pixels, 0)).isNaN();
        assertThat(pixels).containsOnly(-7);
        float[] through = new float[6]; // the camera's plane cuts it: rays start inside it
        KnownShapes.putBox(new Sphere(new Vector3f(0, 0, 20.2f), 0.5f, new Color(1, 2, 3)), through, 0);
        assertThat(footprint.put(through, 0, 0, 0, pixels, 0)).isNegative(); // the near side lies behind the plane
        assertThat(pixels).containsExactly(935, 515, 985, 565);
    }

    @Test
    void onTheThousandSpheresOfTheWalkthroughARayTestsAboutOneSphereWhereTheTreeTestsTwelve() throws Exception {
        // docs/walkthrough.md: at 480 × 270 the tree takes 11.81 tests a ray, the grid 1.17 (152,012
        // tests): a ray tests the sphere in front, and few behind it. Tested in its cell in file
        // order, without the stop, each ray would test every sphere whose patch covers it.
        Scene scene = rtd.io.SceneIO.readScene(java.nio.file.Path.of("examples/thousand_spheres.txt"));
        ViewGrid grid = ViewGrid.build(scene, 480, 270, 1, 1);
        rtd.render.RenderResult result = rtd.render.ParallelRenderer.render(scene.camera(), grid::newTracer,
                tracer -> (rays, hits, i) -> rtd.image.Rgb.BLACK, 480, 270, 1, new rtd.render.RenderProgress());
        assertThat(result.work().intersectionTests()).isEqualTo(152_012);
        assertThat(result.work().testsPerRay()).isLessThan(1.2);
    }

    @Test
    void whereHundredsOfObjectsCoverEveryCellTheyAreSortedNearestFirstAllTheSame() {
        // 300 large spheres and boxes around the origin, some behind the eye, seen through both
        // cameras: cells of hundreds of objects, which are sorted another way than the usual dozen.
        Random random = new Random(13);
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < 300; i++) {
            Vector3f centre = new Vector3f(random.nextFloat() * 4 - 2, random.nextFloat() * 4 - 2, random.nextFloat() * 40 - 20);
            objects.add(i % 3 == 0 ? rtd.geometry.Box.between(centre, centre.add(new Vector3f(3, 3, 0.5f)), new Color(i % 256, 0, 0),
                    rtd.geometry.Material.DEFAULT) : new Sphere(centre, 2 + random.nextFloat() * 3, new Color(0, i % 256, 0)));
        }
        for (ICamera camera : new ICamera[] {new PerspectiveCamera(new Vector3f(0, 0, 15), new Vector3f(0, 0, -1), 60),
            new OrthographicCamera(new Vector3f(0, 0, 25), new Vector3f(0.1f, 0, -1), 12)}) {
            Scene scene = new Scene(new Color(0, 0, 0), camera, objects);
            ViewGrid grid = ViewGrid.build(scene, WIDTH, HEIGHT, 1, 1);
            assertThat(grid.entries() / grid.cellCount()).as("objects a cell").isGreaterThan(32);
            assertThat(checkEveryPixel(scene, grid, 1, 0)).hasSize(WIDTH * HEIGHT);
        }
    }

    @Test
    void whenTheCellSidesSampleMissesTheObjectsThatCoverThePictureTheCellsGrowInstead() {
        // 8,192 spheres: the even ones tiny, the odd ones large enough to cover the whole picture.
        // The cell side is estimated on every second object, the tiny ones: pixel-sized cells
        // would then hold 4,096 objects each, 8.5 billion entries. The builder counts, and grows.
        List<IGeometry> objects = new ArrayList<>();
        Random random = new Random(17);
        for (int i = 0; i < 8_192; i++) {
            Vector3f centre = new Vector3f(random.nextFloat() * 30 - 15, random.nextFloat() * 16 - 8, -100 - i % 2 * 100);
            objects.add(new Sphere(centre, i % 2 == 0 ? 0.05f : 80, new Color(i % 256, 0, 0)));
        }
        Scene scene = new Scene(new Color(0, 0, 0),
                new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50), objects);
        ViewGrid grid = ViewGrid.build(scene, 1920, 1080, 1, 2);
        assertThat((long) grid.entries()).isPositive().isLessThanOrEqualTo(1L << 25);
        assertThat(grid.cellSide()).isGreaterThan(1);
        ViewGridTracer tracer = grid.newTracer();
        RayBundle bundle = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        for (int square = 0; square < 40; square++) {
            int left = random.nextInt(1920 / 8) * 8;
            int top = random.nextInt(1080 / 8) * 8;
            bundle.fill(scene.camera(), left, top, left + 8, top + 8, 1920, 1080);
            tracer.traceAll(bundle, hits);
            for (int i = 0; i < 64; i++) {
                assertSame(hits.hit(i, bundle, objects), scene.nearestHit(bundle.ray(i)), "square at " + left + ", " + top);
            }
        }
    }

    @Test
    void aSquareOfRaysBeyondThePictureIsTracedByTheLoop() {
        Scene mixed = MixedScenes.generate(19, 200);
        Scene scene = new Scene(mixed.ambient(), new PerspectiveCamera(new Vector3f(0, 0, 40), new Vector3f(0, 0, -1), 60),
                mixed.objects());
        ViewGridTracer tracer = ViewGrid.build(scene, WIDTH, HEIGHT, 1, 1).newTracer();
        RayBundle bundle = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        int hit = 0;
        for (int[] square : new int[][] {{WIDTH, 0}, {-8, 8}, {8, HEIGHT}, {16, -8}}) {
            bundle.fill(scene.camera(), square[0], square[1], square[0] + 8, square[1] + 8, WIDTH, HEIGHT);
            tracer.traceAll(bundle, hits);
            for (int i = 0; i < 64; i++) {
                Hit expected = scene.nearestHit(bundle.ray(i));
                assertSame(hits.hit(i, bundle, scene.objects()), expected, "square at " + square[0] + ", " + square[1]);
                hit += expected == null ? 0 : 1;
            }
        }
        assertThat(hit).as("rays beyond the picture that hit something").isGreaterThan(50);
    }

    @Test
    void aCrowdedCellIsSortedByDistanceNegativeOnesTooThenByPlace() {
        float[] nearestByPlace = {3, -2, Float.NEGATIVE_INFINITY, -0.5f, 3, 0, -7};
        int[] places = {9, 0, 1, 2, 3, 4, 5, 6, 9}; // the cell is places[1 .. 8)
        ViewGridBuilder.sortCrowded(places, 1, 8, nearestByPlace);
        assertThat(places).containsExactly(9, 2, 6, 1, 3, 5, 0, 4, 9);
    }

    @Test
    void isTheSameForOneThreadTwoAndThree() {
        Scene scene = manySmallSpheres();
        ViewGrid one = ViewGrid.build(scene, 1920, 1080, 1, 1);
        for (int threads : new int[] {2, 3}) {
            ViewGrid more = ViewGrid.build(scene, 1920, 1080, 1, threads);
            assertThat(more.shift).isEqualTo(one.shift);
            assertThat(more.cellStart).isEqualTo(one.cellStart);
            assertThat(more.places).isEqualTo(one.places);
            assertThat(more.nearest).isEqualTo(one.nearest);
            assertThat(more.objects.leaves.fileOrder).isEqualTo(one.objects.leaves.fileOrder);
            assertThat(more.objects.leaves.numbers).isEqualTo(one.objects.leaves.numbers);
        }
        assertThat(one.entries()).isGreaterThan(scene.objects().size());
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {21, 22, 23})
    void withLightsTheCamerasRaysTakeTheGridAndTheOthersTheTreeAndThePictureIsTheTrees(long seed) {
        Scene mixed = MixedScenes.shaded(MixedScenes.generate(seed, 250), seed);
        Scene scene = new Scene(mixed.ambient(), randomCamera(new Random(seed)), mixed.objects(), mixed.lights());
        ViewGrid grid = ViewGrid.build(scene, WIDTH, HEIGHT, 1, 2);
        Bvh bvh = Bvh.build(scene);
        java.util.function.Function<rtd.render.Tracer, rtd.render.Shader> shaders =
                tracer -> new rtd.shade.WhittedShader(scene, tracer);
        rtd.render.RenderResult both = rtd.render.ParallelRenderer.render(scene.camera(), () -> grid.newTracer(bvh.newTracer()),
                shaders, WIDTH, HEIGHT, 2, new rtd.render.RenderProgress());
        rtd.render.RenderResult tree = rtd.render.ParallelRenderer.render(scene.camera(), bvh::newTracer, shaders, WIDTH,
                HEIGHT, 2, new rtd.render.RenderProgress());
        assertThat(both.image().rgb()).isEqualTo(tree.image().rgb());
        assertThat(both.work().secondaryRays()).isEqualTo(tree.work().secondaryRays()).isNotEmpty();
        assertThat(both.work().rays()).isEqualTo(tree.work().rays());
    }

    @Test
    void aRayThatIsNotTheCamerasFindsTheLoopsHitToo() {
        Scene mixed = MixedScenes.generate(11, 200);
        Scene scene = new Scene(mixed.ambient(), randomCamera(new Random(11)), mixed.objects());
        ViewGridTracer tracer = ViewGrid.build(scene, WIDTH, HEIGHT, 1, 1).newTracer();
        Random random = new Random(11);
        for (int r = 0; r < 2_000; r++) {
            Ray ray = MixedScenes.ray(random, scene);
            assertSame(tracer.nearestHit(ray), scene.nearestHit(ray), "ray " + r + " " + ray);
        }
    }

    /** A triangle seen through a camera whose rays' directions are some 1e20 long. */
    static Scene raysTooLongForANarrowerRounding() {
        return new Scene(new Color(0, 0, 0),
                new PerspectiveCamera(new Vector3f(333333344, 333333344, 1e9f), new Vector3f(666766656, -333433344, -1e9f),
                        1.9e-17f),
                List.of(new rtd.geometry.Triangle(new Vector3f(0, 0, 0), new Vector3f(1e9f, 0, 0), new Vector3f(0, 1e9f, 0),
                        new Color(255, 0, 0), rtd.geometry.Material.DEFAULT)));
    }
}
