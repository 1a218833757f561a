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
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.render.WorkCount;
import rtd.scene.Scene;
import rtd.testing.MixedScenes;
import rtd.testing.RandomScenes;

/**
 * The image of hits, found object by object, gives every pixel the paper's loop's hit, bit for
 * bit: for random scenes of every kind of object seen by random cameras of both kinds, where
 * rounding lets the test hit far beside small spheres, and for any number of threads.
 */
@DisplayName("The image of hits finds the loop's hit for every pixel")
class HitImageTest {

    private static final int WIDTH = 150;
    private static final int HEIGHT = 70; // not a whole number of tiles either way

    /**
     * Asks the image for every pixel's ray in squares of 8 × 8 as the renderer does, each square
     * first at once, and checks each against the loop; answers the hits.
     */
    private static List<Hit> checkEveryPixel(Scene scene, HitImage image, boolean hitPointsRead) {
        HitImageTracer tracer = image.newTracer();
        RayBundle bundle = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        hits.readHitPoints(hitPointsRead);
        List<Hit> found = new ArrayList<>();
        for (int top = 0; top < HEIGHT; top += 8) {
            for (int left = 0; left < WIDTH; left += 8) {
                int right = Math.min(WIDTH, left + 8);
                int bottom = Math.min(HEIGHT, top + 8);
                bundle.fill(scene.camera(), left, top, right, bottom, WIDTH, HEIGHT);
                if (!tracer.traceAtOnce(bundle, hits)) {
                    tracer.traceAll(bundle, hits);
                } else if (hitPointsRead) {
                    assertThat(hits.missedAll()).as("a square whose hit points are read, at once").isTrue();
                }
                for (int i = 0; i < bundle.count(); i++) {
                    Ray ray = bundle.ray(i);
                    Hit expected = scene.nearestHit(ray);
                    String what = "pixel (" + (left + i % (right - left)) + ", " + (top + i / (right - left)) + ") " + ray;
                    if (hitPointsRead) {
                        assertSame(hits.hit(i, bundle, scene.objects()), expected, what);
                    } else {
                        assertThat(hits.index(i)).as(what).isEqualTo(expected == null ? -1 : expected.index());
                    }
                    if (expected != null) {
                        found.add(expected);
                    }
                }
            }
        }
        return found;
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})
    void forEveryPixelOfRandomScenesSeenByRandomCamerasOfBothKinds(long seed) {
        Scene mixed = MixedScenes.generate(seed, 100 + (int) (seed * 89 % 300));
        Random random = new Random(seed);
        int hits = 0;
        for (int view = 0; view < 4; view++) {
            Scene scene = new Scene(mixed.ambient(), ViewGridTest.randomCamera(random), mixed.objects());
            HitImage image = HitImage.build(scene, WIDTH, HEIGHT, 1, false);
            hits += checkEveryPixel(scene, image, true).size();
            checkEveryPixel(scene, image, false);
        }
        assertThat(hits).as("rays that hit something").isGreaterThan(10_000);
    }

    /**
     * A mesh keeps its triangles' numbers side by side in a few shared arrays, and the image of
     * hits tests a triangle where they lie ({@code Triangle.hit}), while it copies spheres'
     * numbers into its tiles: a hilly grid of triangles in blocks of 50 (so at offsets other than
     * 0, in several arrays), with spheres before, among and after them in the file.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void forEveryPixelOfAMeshWhoseTrianglesShareArraysAmongSpheres(long seed) {
        Random random = new Random(seed);
        List<IGeometry> objects = new ArrayList<>();
        addSpheres(objects, random, 10);
        int side = 12;
        float[][] heights = new float[side + 1][side + 1];
        for (float[] row : heights) {
            for (int i = 0; i < row.length; i++) {
                row[i] = random.nextFloat() * 2 - 1;
            }
        }
        float[] block = null;
        int inBlock = 50;
        for (int z = 0; z < side; z++) {
            for (int x = 0; x < side; x++) {
                Vector3f[] quad = {corner(heights, x, z, side), corner(heights, x + 1, z, side),
                    corner(heights, x + 1, z + 1, side), corner(heights, x, z + 1, side)};
                for (int half = 0; half < 2; half++) {
                    if (inBlock == 50) {
                        block = new float[50 * rtd.geometry.Triangle.NUMBERS];
                        inBlock = 0;
                    }
                    int at = rtd.geometry.Triangle.NUMBERS * inBlock++;
                    rtd.geometry.TriangleNumbers.putNumbers(quad[0], quad[1 + half], quad[2 + half], block, at);
                    objects.add(new rtd.geometry.Triangle(block, at, null, new Color(10 * x, 10 * z, half * 200),
                            rtd.geometry.Material.DEFAULT));
                }
                if (random.nextInt(40) == 0) {
                    addSpheres(objects, random, 1);
                }
            }
        }
        addSpheres(objects, random, 10);
        int triangleHits = 0;
        for (int view = 0; view < 4; view++) {
            Scene scene = new Scene(new Color(0, 0, 0), cameraOnTheMesh(random), objects);
            for (Hit hit : checkEveryPixel(scene, HitImage.build(scene, WIDTH, HEIGHT, 1 + view % 2, false), true)) {
                triangleHits += scene.objects().get(hit.index()) instanceof rtd.geometry.Triangle ? 1 : 0;
            }
        }
        assertThat(triangleHits).as("pixels that show a triangle").isGreaterThan(10_000);
    }

    /** A camera of either kind above the mesh, looking at a point of it, steeply or nearly along it. */
    private static ICamera cameraOnTheMesh(Random random) {
        Vector3f position = new Vector3f(random.nextFloat() * 12 - 6, 1.5f + random.nextFloat() * 8,
                random.nextFloat() * 12 - 6);
        Vector3f target = new Vector3f(random.nextFloat() * 4 - 2, 0, random.nextFloat() * 4 - 2);
        Vector3f direction = target.subtract(position);
        return random.nextBoolean() ? new PerspectiveCamera(position, direction, 40 + random.nextFloat() * 60)
                : new OrthographicCamera(position, direction, 10 + random.nextFloat() * 15);
    }

    private static Vector3f corner(float[][] heights, int x, int z, int side) {
        return new Vector3f(8f * x / side - 4, heights[x][z], 8f * z / side - 4);
    }

    private static void addSpheres(List<IGeometry> objects, Random random, int count) {
        for (int i = 0; i < count; i++) {
            objects.add(new Sphere(new Vector3f(random.nextFloat() * 8 - 4, random.nextFloat() * 3 - 1,
                    random.nextFloat() * 8 - 4), 0.1f + random.nextFloat() * 0.5f, new Color(255, 255, 0)));
        }
    }

    /**
     * A camera of a field of view of 1.9e-17°, whose rays are some 1e20 long: there the triangle
     * test's float products overflow, and a triangle rounds as it may for any ray (a review found
     * every pixel red by the loop and black by the image and the grid before the camera's rays were
     * checked against {@link IGeometry#LONGEST_DIRECTION}).
     */
    @Test
    void aCameraWhoseRaysAreTooLongForTheTrianglesNarrowerRoundingGetsTheWiderOne() {
        Scene scene = raysTooLongForANarrowerRounding();
        rtd.shade.FlatShader flat = new rtd.shade.FlatShader(scene);

        int[] loop = rtd.render.ParallelRenderer.render(scene.camera(), () -> new rtd.render.LinearTracer(scene),
                tracer -> flat, 100, 60, 1, new rtd.render.RenderProgress()).image().rgb();
        int[] image = rtd.render.ParallelRenderer.render(scene.camera(), HitImage.build(scene, 100, 60, 1)::newTracer,
                tracer -> flat, 100, 60, 1, new rtd.render.RenderProgress()).image().rgb();

        assertThat(image).isEqualTo(loop);
        assertThat(java.util.Arrays.stream(loop).filter(rgb -> rgb == 0xFF0000).count()).as("red pixels").isGreaterThan(1_500);
    }

    /** A triangle seen through a camera whose rays' directions are some 1e20 long. */
    static Scene raysTooLongForANarrowerRounding() {
        return new Scene(new Color(0, 0, 0),
                new PerspectiveCamera(new Vector3f(333333344, 333333344, 1e9f), new Vector3f(666766656, -333433344, -1e9f),
                        1.9e-17f),
                List.of(new rtd.geometry.Triangle(new Vector3f(0, 0, 0), new Vector3f(1e9f, 0, 0), new Vector3f(0, 1e9f, 0),
                        new Color(255, 0, 0), rtd.geometry.Material.DEFAULT)));
    }

    @Test
    void evenWhereRoundingLetsTheTestHitFarBesideSmallSpheresSeenFromAfar() {
        Vector3f along = new Vector3f(0.3f, -0.2f, -1);
        assertFindsHitsBesideSmallSpheres(new OrthographicCamera(along.normalize().multiply(-2000), along, 60), 7);
        Vector3f direction = new Vector3f(-0.2f, 0.1f, -1);
        assertFindsHitsBesideSmallSpheres(new PerspectiveCamera(direction.normalize().multiply(-3000), direction, 0.03f), 9);
    }

    /** Sixty small spheres seen from thousands of units away: every pixel as the loop's, and hits well beside them. */
    private static void assertFindsHitsBesideSmallSpheres(ICamera camera, long seed) {
        Scene scene = ViewGridTest.smallSpheres(camera, seed);
        ViewGridTest.assertSomeHitsLieBeside(checkEveryPixel(scene, HitImage.build(scene, WIDTH, HEIGHT, 1, false), true));
    }

    @Test
    void theImageIsTheSameForAnyNumberOfThreads() {
        Scene scene = RandomScenes.generate(5, 30_000); // enough objects to build in parallel
        HitImage one = HitImage.build(scene, 320, 180, 1, false);
        for (int threads : new int[] {2, 3}) {
            HitImage more = HitImage.build(scene, 320, 180, threads, false);
            assertThat(more.index).as("objects, %d threads", threads).isEqualTo(one.index);
            assertThat(more.t).as("t, %d threads", threads).isEqualTo(one.t);
            assertThat(more.distance).as("distances, %d threads", threads).isEqualTo(one.distance);
            assertThat(more.testsOfKind).as("tests, %d threads", threads).isDeepEqualTo(one.testsOfKind);
            assertThat(more.entries()).isEqualTo(one.entries());
        }
        assertThat(java.util.Arrays.stream(one.index).filter(i -> i >= 0).count()).as("pixels that show a sphere")
                .isGreaterThan(10_000);
        Scene mixed = MixedScenes.generate(8, 3_000); // several kinds, met by the threads in an order of their own
        HitImage first = HitImage.build(mixed, 160, 90, 1, false);
        for (int run = 0; run < 4; run++) {
            HitImage again = HitImage.build(mixed, 160, 90, 2 + run % 2, false);
            assertThat(again.kindNames).as("kinds, run %d", run).containsExactly(first.kindNames);
            assertThat(again.testsOfKind).as("tests by kind, run %d", run).isDeepEqualTo(first.testsOfKind);
            assertThat(again.index).isEqualTo(first.index);
        }
        assertThat(first.kindNames).hasSizeGreaterThan(2);
    }

    @Test
    void aPictureOfMoreThan3840By2160PixelsIsLeftToTheViewGrid() {
        Scene scene = RandomScenes.generate(3, 50);
        assertThat(HitImage.build(scene, 4096, 2048, 1)).isNotNull(); // 8,388,608 pixels, the most
        assertThat(HitImage.build(scene, 4096, 2049, 1)).isNull();
    }

    @Test
    void objectsThatHideEachOtherDeeplyAreLeftToTheViewGrid() {
        // Spheres of radius 100 around the origin, each filling the picture of 160 × 90: each is
        // tested on all 14,400 pixels. Thirty-two are 32 tests a pixel, the most; thirty-three
        // are more.
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 200), new Vector3f(0, 0, -1), 20);
        assertThat(HitImage.build(coveringSpheres(camera, 33), 160, 90, 1)).isNull();
        HitImage fits = HitImage.build(coveringSpheres(camera, 32), 160, 90, 1);
        assertThat(fits).isNotNull();
        assertThat(fits.entries()).isEqualTo(32 * 6);
        assertThat(fits.testsOfKind[0]).containsOnly(32);
    }

    private static Scene coveringSpheres(ICamera camera, int count) {
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            objects.add(new Sphere(new Vector3f(0, 0, -i * 0.001f), 100, new Color(i % 256, 0, 0)));
        }
        return new Scene(new Color(0, 0, 0), camera, objects);
    }

    @Test
    void eachPixelCountsTheTestsOfTheObjectsWhoseFootprintHoldsItAndOfEveryPlane() {
        // Camera at z = 20 looking down −z, 10 pixels a unit, 100 × 60: pixel x's ray runs at
        // x = (x − 50) / 10, pixel y's at y = (30 − y) / 10. A sphere of radius 1 at the origin
        // has the box ±1.002 (Sphere.bounds), grown by rounding by a few millionths: its
        // footprint is the pixels whose rays pass within it, x from 40 to 60 (39 runs at −1.1)
        // and y from 20 to 40, 21 × 21 pixels.
        OrthographicCamera camera = new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 10);
        Sphere sphere = new Sphere(new Vector3f(0, 0, 0), 1, new Color(1, 2, 3));
        Plane floor = new Plane(new Vector3f(0, 0, -5), new Vector3f(0, 0, 1), new Color(4, 5, 6),
                rtd.geometry.Material.DEFAULT);
        Scene scene = new Scene(new Color(0, 0, 0), camera, List.of(sphere, floor));
        HitImage image = HitImage.build(scene, 100, 60, 1);
        HitImageTracer tracer = image.newTracer();
        RayBundle square = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        long tests = 0;
        for (int top = 0; top < 60; top += 8) {
            for (int left = 0; left < 100; left += 8) {
                square.fill(camera, left, top, Math.min(100, left + 8), Math.min(60, top + 8), 100, 60);
                tracer.traceAll(square, hits);
                for (int i = 0; i < square.count(); i++) {
                    int x = left + i % (Math.min(100, left + 8) - left);
                    int y = top + i / (Math.min(100, left + 8) - left);
                    boolean inFootprint = x >= 40 && x <= 60 && y >= 20 && y <= 40;
                    assertThat(hits.tests(i)).as("pixel (%d, %d)", x, y).isEqualTo(inFootprint ? 2 : 1);
                    assertThat(hits.index(i)).as("pixel (%d, %d)", x, y).isIn(0, 1);
                    tests += hits.tests(i);
                }
            }
        }
        WorkCount work = tracer.work();
        assertThat(work.rays()).isEqualTo(6_000);
        assertThat(work.testsByKind()).containsEntry("plane", 6_000L).containsEntry("sphere", 21L * 21);
        assertThat(work.intersectionTests()).isEqualTo(tests);
    }

    @Test
    void onTheThousandSpheresOfTheWalkthroughEachSphereIsTestedOnEveryPixelOfItsPatch() throws Exception {
        // docs/walkthrough.md: at 480 × 270 the image of hits takes 2.60 tests a ray (336,530),
        // the view grid 1.17: every sphere is tested on its whole patch, hidden or not.
        Scene scene = rtd.io.SceneIO.readScene(java.nio.file.Path.of("examples/thousand_spheres.txt"));
        HitImage image = HitImage.build(scene, 480, 270, 2);
        for (boolean pointsRead : new boolean[] {true, false}) { // squares of one sphere answered at once, or not
            java.util.concurrent.atomic.AtomicLong perRay = new java.util.concurrent.atomic.AtomicLong(); // as --view cost reads them
            rtd.render.Shader counting = new rtd.render.Shader() {
                @Override
                public rtd.image.Rgb colour(RayBundle rays, HitBuffer hits, int i) {
                    perRay.addAndGet(hits.tests(i));
                    return rtd.image.Rgb.BLACK;
                }

                @Override
                public boolean readsHitPoints() {
                    return pointsRead;
                }
            };
            rtd.render.ParallelRenderer.render(scene.camera(), image::newTracer, tracer -> counting, 480, 270, 2,
                    new rtd.render.RenderProgress());
            assertThat(perRay.get()).as("the rays' own counts, hit points read: %s", pointsRead).isEqualTo(336_530);
        }
        rtd.render.RenderResult result = rtd.render.ParallelRenderer.render(scene.camera(), image::newTracer,
                tracer -> (rays, hits, i) -> rtd.image.Rgb.BLACK, 480, 270, 2, new rtd.render.RenderProgress());
        assertThat(java.util.Arrays.stream(image.testsOfKind[0]).asLongStream().sum()).isEqualTo(336_530);
        assertThat(result.work().intersectionTests()).isEqualTo(336_530);
        assertThat(result.work().rays()).isEqualTo(480 * 270);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void withFlatColoursThePictureIsALookupOfEachPixelsObjectTheSameAsRayByRay(long seed) {
        Scene mixed = MixedScenes.generate(seed, 300); // planes among them: every ray tests those
        Scene scene = new Scene(mixed.ambient(), ViewGridTest.randomCamera(new Random(seed)), mixed.objects());
        HitImage image = HitImage.build(scene, WIDTH, HEIGHT, 2, false);
        rtd.shade.FlatShader flat = new rtd.shade.FlatShader(scene);
        assertThat(image.newTracer().traceEveryPixel(scene.camera(), WIDTH, HEIGHT)).as("the image's own picture").isNotNull();
        assertThat(image.newTracer().traceEveryPixel(scene.camera(), WIDTH + 1, HEIGHT)).as("another picture").isNull();

        rtd.render.RenderResult lookup = rtd.render.ParallelRenderer.render(scene.camera(), image::newTracer,
                tracer -> flat, WIDTH, HEIGHT, 2, new rtd.render.RenderProgress());
        rtd.render.RenderResult rayByRay = rtd.render.ParallelRenderer.render(scene.camera(),
                () -> withoutTheWholePicture(image.newTracer()), tracer -> flat, WIDTH, HEIGHT, 2,
                new rtd.render.RenderProgress());

        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                assertThat(lookup.image().rgb(x, y)).as("pixel (%d, %d)", x, y).isEqualTo(rayByRay.image().rgb(x, y));
            }
        }
        assertThat(lookup.work().rays()).isEqualTo((long) WIDTH * HEIGHT).isEqualTo(rayByRay.work().rays());
        assertThat(lookup.work().testsByKind()).isEqualTo(rayByRay.work().testsByKind());
        assertThat(lookup.work().intersectionTests()).isEqualTo(rayByRay.work().intersectionTests());
    }

    /** {@code tracer} as it answers bundles of rays, without its answer for the whole picture at once. */
    private static Tracer withoutTheWholePicture(Tracer tracer) {
        return new Tracer() {
            @Override
            public Hit nearestHit(Ray ray) {
                return tracer.nearestHit(ray);
            }

            @Override
            public void traceAll(RayBundle rays, HitBuffer hits) {
                tracer.traceAll(rays, hits);
            }

            @Override
            public boolean traceAtOnce(RayBundle rays, HitBuffer hits) {
                return tracer.traceAtOnce(rays, hits);
            }

            @Override
            public long testsRun() {
                return tracer.testsRun();
            }

            @Override
            public WorkCount work() {
                return tracer.work();
            }
        };
    }

    @Test
    void aRayThatIsNotOneOfTheImagesFindsTheLoopsHitToo() {
        Scene mixed = MixedScenes.generate(11, 200);
        Scene scene = new Scene(mixed.ambient(), ViewGridTest.randomCamera(new Random(11)), mixed.objects());
        HitImageTracer tracer = HitImage.build(scene, WIDTH, HEIGHT, 1, false).newTracer();
        Random random = new Random(11);
        for (int r = 0; r < 500; r++) {
            Ray ray = MixedScenes.ray(random, scene);
            assertSame(tracer.nearestHit(ray), scene.nearestHit(ray), "ray " + r + " " + ray);
        }
        RayBundle samples = new RayBundle(64); // rays through the middles of their pixels: not the image's
        HitBuffer hits = new HitBuffer(64);
        samples.fill(scene.camera(), 40, 16, 48, 24, WIDTH, HEIGHT, 0.5f, 0.5f);
        tracer.traceAll(samples, hits);
        for (int i = 0; i < samples.count(); i++) {
            assertSame(hits.hit(i, samples, scene.objects()), scene.nearestHit(samples.ray(i)), "sample " + i);
        }
    }
}
