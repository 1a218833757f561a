package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;
import static rtd.accel.SameHit.assertSame;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.ParallelRenderer;
import rtd.render.RayBundle;
import rtd.render.RenderProgress;
import rtd.scene.Scene;
import rtd.shade.FlatShader;
import rtd.testing.MixedScenes;
import rtd.testing.Renders;
import rtd.testing.TransformedScenes;

/**
 * The image of hits gives every pixel the paper's loop's hit, bit for bit: for random flat scenes of every kind of
 * object (spheres from tiny to large, triangles, boxes, planes, cylinders and cones, which the engine does not know,
 * exact ties) seen by random cameras of both kinds, from inside and outside the scene; for objects behind the camera,
 * huge ones around it, and small ones seen from afar where rounding lets the test hit beside them; the same for any
 * number of threads.
 */
@DisplayName("The image of hits finds the loop's hit for every pixel")
class HitImageTest {

    private static final int WIDTH = 150; // three tiles across, the last one cut short
    private static final int HEIGHT = 70;

    /**
     * Traces every pixel's ray as the renderer does, in squares of 8 × 8, and checks each against the loop, and its
     * tests against the footprints that hold its pixel; answers the hits.
     */
    private static List<Hit> checkEveryPixel(Scene scene, HitImage image) {
        int[] footprints = new int[4 * scene.objects().size()];
        ImageFootprint footprint = ImageFootprint.of(scene.camera(), WIDTH, HEIGHT, 0);
        for (int f = 0; f < scene.objects().size(); f++) {
            footprint.putObject(scene.objects().get(f), new float[6], footprints, 4 * f);
        }
        HitImageTracer tracer = image.newTracer();
        RayBundle bundle = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        List<Hit> found = new ArrayList<>();
        for (int top = 0; top < HEIGHT; top += 8) {
            for (int left = 0; left < WIDTH; left += 8) {
                int right = Math.min(WIDTH, left + 8);
                bundle.fill(scene.camera(), left, top, right, Math.min(HEIGHT, top + 8), WIDTH, HEIGHT);
                tracer.traceAll(bundle, hits);
                for (int i = 0; i < bundle.count(); i++) {
                    Ray ray = bundle.ray(i);
                    Hit expected = scene.nearestHit(ray);
                    assertSame(hits.hit(i, bundle, scene.objects()), expected,
                            "pixel (" + (left + i % (right - left)) + ", " + (top + i / (right - left)) + ") " + ray);
                    int x = left + i % (right - left);
                    int y = top + i / (right - left);
                    assertThat(hits.tests(i)).as("the tests of pixel (%d, %d)", x, y)
                            .isEqualTo(image.unbounded.length + holding(footprints, x, y));
                    if (expected != null) {
                        found.add(expected);
                    }
                }
            }
        }
        return found;
    }

    /** How many of the {@code footprints} (x0, y0, x1, y1 inclusive, each object's) hold pixel (x, y). */
    private static int holding(int[] footprints, int x, int y) {
        int count = 0;
        for (int at = 0; at < footprints.length; at += 4) {
            count += footprints[at] <= x && x <= footprints[at + 2] && footprints[at + 1] <= y && y <= footprints[at + 3]
                    ? 1 : 0;
        }
        return count;
    }

    @ParameterizedTest(name = "several kinds with a box: {0}")
    @ValueSource(booleans = {false, true})
    void countsEachKindsTestsAsThePixelsRanThem(boolean severalKinds) {
        Scene mixed = MixedScenes.generate(3, 300);
        List<IGeometry> objects = severalKinds ? mixed.objects()
                : mixed.objects().stream().filter(o -> o instanceof Sphere || o instanceof Plane).toList();
        Scene scene = new Scene(mixed.ambient(), ViewGridTest.randomCamera(new Random(3)), objects);
        HitImage image = HitImage.build(scene, WIDTH, HEIGHT, 1);
        HitImageTracer tracer = image.newTracer();
        RayBundle bundle = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        for (int top = 0; top < HEIGHT; top += 8) {
            for (int left = 0; left < WIDTH; left += 8) {
                bundle.fill(scene.camera(), left, top, Math.min(WIDTH, left + 8), Math.min(HEIGHT, top + 8), WIDTH,
                        HEIGHT);
                tracer.traceAll(bundle, hits);
            }
        }
        assertThat(image.tests == null).as("one kind: no tests by kind kept per pixel").isEqualTo(!severalKinds);
        assertThat(image.unbounded).as("planes, tested on every pixel").isNotEmpty();
        assertThat(tracer.work().testsByKind()).isEqualTo(testsByKind(scene)).hasSizeGreaterThan(1);
    }

    /** Each kind's tests over the picture: an object's on the pixels of its footprint, one without a box's on all. */
    private static Map<String, Long> testsByKind(Scene scene) {
        ImageFootprint footprint = ImageFootprint.of(scene.camera(), WIDTH, HEIGHT, 0);
        Map<String, Long> byKind = new TreeMap<>();
        int[] pixels = new int[4];
        float[] box = new float[6];
        for (IGeometry object : scene.objects()) {
            footprint.putObject(object, box, pixels, 0);
            long tests = !ImageFootprint.isFinite(box) ? WIDTH * HEIGHT
                    : Math.max(0, pixels[2] - pixels[0] + 1) * (long) (pixels[3] - pixels[1] + 1);
            byKind.merge(object.kind(), tests, Long::sum);
        }
        return byKind;
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {2, 5, 8, 11, 14})
    void forEveryPixelOfRandomScenesSeenByRandomCamerasOfBothKinds(long seed) {
        Scene mixed = MixedScenes.generate(seed, 100 + (int) (seed * 89 % 300));
        Random random = new Random(seed);
        int hits = 0;
        for (int view = 0; view < 4; view++) {
            Scene scene = new Scene(mixed.ambient(), ViewGridTest.randomCamera(random), mixed.objects());
            hits += checkEveryPixel(scene, HitImage.build(scene, WIDTH, HEIGHT, 1)).size();
        }
        assertThat(hits).as("rays that hit something").isGreaterThan(10_000);
    }

    @ParameterizedTest(name = "perspective {0}")
    @ValueSource(booleans = {false, true})
    void forTinyAndHugeObjectsObjectsBehindTheCameraAndAPlane(boolean perspective) {
        ICamera camera = perspective ? new PerspectiveCamera(new Vector3f(0, 0, 0), new Vector3f(0, 0, -1), 70)
                : new OrthographicCamera(new Vector3f(0, 0, 0), new Vector3f(0, 0, -1), 8);
        Random random = new Random(5);
        List<IGeometry> objects = new ArrayList<>();
        objects.add(new Sphere(new Vector3f(0, 0, 0), 500, new Color(1, 1, 1))); // around the camera: hit from inside
        for (int i = 0; i < 400; i++) { // before and behind the camera, from a thousandth to three units
            Vector3f centre = new Vector3f(random.nextFloat() * 8 - 4, random.nextFloat() * 6 - 3, random.nextFloat() * 20 - 10);
            float radius = i % 4 == 0 ? 0.001f : random.nextFloat() * 3;
            objects.add(new Sphere(centre, radius, new Color(i % 256, 7, 9)));
        }
        objects.add(new Plane(new Vector3f(0, -2, 0), new Vector3f(0.1f, 1, 0.2f), new Color(3, 2, 1), Material.DEFAULT));
        Scene scene = new Scene(new Color(0, 0, 0), camera, objects);
        assertThat(checkEveryPixel(scene, HitImage.build(scene, WIDTH, HEIGHT, 1))).hasSize(WIDTH * HEIGHT);
    }

    @Test
    void ofTwoEqualSpheresTheFirstInTheFileWinsEveryPixel() {
        Scene scene = new Scene(new Color(0, 0, 0), new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 4),
                List.of(new Sphere(new Vector3f(0, 0, 0), 3, new Color(1, 0, 0)),
                        new Sphere(new Vector3f(0, 0, 0), 3, new Color(0, 1, 0))));
        HitImage image = HitImage.build(scene, WIDTH, HEIGHT, 1);
        assertThat(image.index).contains(0).doesNotContain(1);
        checkEveryPixel(scene, image);
    }

    @Test
    void evenWhereRoundingLetsTheTestHitFarBesideSmallSpheresSeenFromAfar() {
        Vector3f direction = new Vector3f(-0.2f, 0.1f, -1);
        Scene scene = ViewGridTest.smallSpheres(new PerspectiveCamera(direction.normalize().multiply(-3000), direction,
                0.03f), 9);
        ViewGridTest.assertSomeHitsLieBeside(checkEveryPixel(scene, HitImage.build(scene, WIDTH, HEIGHT, 1)));
    }

    @Test
    void isTheSameForOneThreadTwoAndThreeAndAnySamplePixelIsTheLoops() {
        Scene scene = ViewGridTest.manySmallSpheres();
        HitImage one = HitImage.build(scene, 400, 200, 1);
        for (int threads : new int[] {2, 3}) {
            HitImage more = HitImage.build(scene, 400, 200, threads);
            assertThat(more.index).isEqualTo(one.index);
            assertThat(more.t).isEqualTo(one.t);
            assertThat(more.distance).isEqualTo(one.distance);
            assertThat(more.tests).isEqualTo(one.tests);
        }
        Random random = new Random(4);
        for (int k = 0; k < 300; k++) {
            int pixel = random.nextInt(400 * 200);
            Hit expected = scene.nearestHit(scene.camera().generateRay(pixel % 400, pixel / 400, 400, 200));
            assertThat(one.index[pixel]).as("pixel %d", pixel).isEqualTo(expected == null ? -1 : expected.index());
        }
        assertThat(java.util.Arrays.stream(one.index).filter(index -> index >= 0).count()).as("pixels that show a sphere")
                .isGreaterThan(400 * 200 / 4);
        assertThat(one.entries()).isGreaterThan(1_000);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {5, 6})
    void drawsThePapersPictureOfTransformedAndPatternedObjectsOnAnyNumberOfThreads(long seed) {
        Scene scene = TransformedScenes.of(MixedScenes.generate(seed, 120), seed);
        int[] paper = Renders.paper(scene, WIDTH, HEIGHT);
        FlatShader flat = new FlatShader(scene);
        for (int threads = 1; threads <= 3; threads++) {
            HitImage image = HitImage.build(scene, WIDTH, HEIGHT, threads);
            assertThat(ParallelRenderer.render(scene.camera(), image::newTracer, tracer -> flat, WIDTH, HEIGHT, threads,
                    new RenderProgress()).image().rgb()).isEqualTo(paper);
        }
    }

    @Test
    void aRayThatIsNotTheImagesFindsTheLoopsHitToo() {
        Scene mixed = MixedScenes.generate(11, 200);
        Scene scene = new Scene(mixed.ambient(), ViewGridTest.randomCamera(new Random(11)), mixed.objects());
        HitImageTracer tracer = HitImage.build(scene, WIDTH, HEIGHT, 1).newTracer();
        Random random = new Random(11);
        for (int r = 0; r < 1_000; r++) {
            Ray ray = MixedScenes.ray(random, scene);
            assertSame(tracer.nearestHit(ray), scene.nearestHit(ray), "ray " + r + " " + ray);
        }
        RayBundle sample = new RayBundle(64);
        HitBuffer hits = new HitBuffer(64);
        sample.fill(scene.camera(), 8, 8, 16, 16, WIDTH, HEIGHT, 0.5f, 0.5f); // through the pixels' middles
        tracer.traceAll(sample, hits);
        for (int i = 0; i < sample.count(); i++) {
            assertSame(hits.hit(i, sample, scene.objects()), scene.nearestHit(sample.ray(i)), "middle of pixel " + i);
        }
    }
}
