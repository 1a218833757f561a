package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static rtd.accel.Grazing.dot;
import static rtd.accel.Grazing.missesExactly;
import static rtd.accel.Grazing.point;
import static rtd.accel.Grazing.unit;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Function;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
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
import rtd.shade.Surface;
import rtd.shade.WhittedShader;
import rtd.testing.MixedScenes;

/**
 * The mirror grids find what a ray that a flat mirror reflects from the camera's eye hits, as the
 * paper's loop does, to the last bit: for random scenes of every kind of object over tilted
 * mirrors, for tiny spheres where rounding lets the test hit beside them, and for rays that pass
 * the mirrored eye as far off as the grid allows and graze a box's outline.
 */
@DisplayName("The mirror grids answer mirrored rays as the loop does")
class MirrorGridTest {

    private static final Material MIRROR = new Material(0.1f, 0.6f, 0.3f, 50, 0.5f, 0, 1);
    private static final Light LIGHT = new Light(new Vector3f(0, 200, 0), new Rgb(1, 1, 1));

    /** The ray the shader reflects at {@code hit} of {@code ray} ({@link WhittedShader}'s step 4). */
    static Ray mirrored(Ray ray, Hit hit) {
        Surface surface = Surface.at(ray, hit);
        Vector3f direction = ray.direction();
        Vector3f normal = surface.normal();
        return new Ray(surface.over(), direction.subtract(normal.multiply(2 * direction.dot(normal))));
    }

    /** Checks {@code ray} against the loop, to the last bit; answers whether a grid served it. */
    static boolean check(Scene scene, MirrorGrids grids, Tracer tracer, Ray ray) {
        Hit loop = scene.nearestHit(ray);
        Hit grid = tracer.nearestHit(ray);
        if (loop == null) {
            assertThat(grid).as("ray " + ray).isNull();
        } else {
            assertThat(grid).as("ray " + ray).isNotNull();
            assertThat(grid.index()).as("object hit by " + ray).isEqualTo(loop.index());
            assertThat(Float.floatToIntBits(grid.t())).as("t of " + ray).isEqualTo(Float.floatToIntBits(loop.t()));
            assertThat(grid.distance()).as("distance of " + ray).isEqualTo(loop.distance());
        }
        return grids.grids().stream().anyMatch(g -> g.cellOf(ray) >= 0);
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 4, 5, 6, 7})
    void everyRayTheShaderMirrorsGetsTheLoopsHit(long seed) {
        Random random = new Random(seed);
        List<IGeometry> objects = new ArrayList<>(MixedScenes.generate(seed, 300).objects());
        if (seed % 2 == 0) {
            objects.removeIf(object -> object instanceof Plane); // and with the random planes, in the odd ones
        }
        Vector3f tilt = new Vector3f((float) random.nextGaussian() * 0.15f, 1, (float) random.nextGaussian() * 0.15f);
        objects.add(random.nextInt(objects.size()), new Plane(new Vector3f(0, -16, 0), tilt.normalize(),
                new Color(200, 200, 200), MIRROR));
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f((random.nextFloat() * 2 - 1) * 20,
                20 + random.nextFloat() * 20, 40), new Vector3f(0, -0.7f, -1), 60);
        Scene scene = new Scene(new Color(0, 0, 0), camera, objects, List.of(LIGHT));
        MirrorGrids grids = MirrorGrids.build(scene, 400, 300, 1, 2);
        Tracer tracer = grids.newTracer(new LinearTracer(scene));

        int served = 0;
        for (int i = 0; i < 20_000; i++) {
            Ray ray = camera.generateRay(random.nextFloat() * 400, random.nextFloat() * 300, 400, 300);
            Hit hit = scene.nearestHit(ray);
            if (hit != null && hit.object() instanceof Plane plane && plane.material() == MIRROR) {
                served += check(scene, grids, tracer, mirrored(ray, hit)) ? 1 : 0;
            }
        }

        assertThat(grids.count()).isEqualTo(1);
        assertThat(served).as("mirrored rays the grid served").isGreaterThan(1_000);
    }

    @Test
    void mirroredRaysPastTinySpheresGetTheLoopsHitWhereRoundingMakesHitsBesideThem() {
        Random random = new Random(7);
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < 400; i++) {
            Vector3f centre = new Vector3f((random.nextFloat() * 2 - 1) * 8, 40 + (random.nextFloat() * 2 - 1) * 8,
                    (random.nextFloat() * 2 - 1) * 8);
            objects.add(new Sphere(centre, 0.0005f + random.nextFloat() * 0.002f, new Color(200, 100, 50)));
        }
        objects.add(new Plane(new Vector3f(0, 0, 0), new Vector3f(0, 1, 0), new Color(200, 200, 200), MIRROR));
        Vector3f eye = new Vector3f(0.5f, 10, 0.25f);
        Vector3f image = new Vector3f(0.5f, -10, 0.25f);
        PerspectiveCamera camera = new PerspectiveCamera(eye, new Vector3f(0, -1, 0), 60);
        Scene scene = new Scene(new Color(0, 0, 0), camera, objects, List.of(LIGHT));
        MirrorGrids grids = MirrorGrids.build(scene, 2048, 2048, 1, 1); // a fine picture: a pixel is a few radii
        Tracer tracer = grids.newTracer(new LinearTracer(scene));

        int served = 0;
        int besides = 0;
        for (int i = 0; i < 6_000; i++) {
            Sphere target = (Sphere) objects.get(random.nextInt(400));
            // the camera ray towards the mirror's point on the line from the eye's image past the sphere, off by up to 20 radii
            Vector3f aim = target.center().add(new Vector3f(random.nextFloat() * 2 - 1, 0, random.nextFloat() * 2 - 1)
                    .multiply(target.radius() * 20 * random.nextFloat()));
            Vector3f towards = aim.subtract(image);
            Vector3f onMirror = image.add(towards.multiply(-image.y() / towards.y()));
            Ray ray = new Ray(eye, onMirror.subtract(eye));
            Hit hit = scene.nearestHit(ray);
            if (hit == null || !(hit.object() instanceof Plane)) {
                continue;
            }
            Ray reflected = mirrored(ray, hit);
            served += check(scene, grids, tracer, reflected) ? 1 : 0;
            Hit loop = scene.nearestHit(reflected);
            if (loop != null && loop.object() instanceof Sphere sphere && missesExactly(reflected, sphere)) {
                besides++;
            }
        }

        assertThat(besides).as("hits the loop reports beside a sphere").isGreaterThan(0);
        assertThat(served).isGreaterThan(5_000);
    }

    @Test
    void raysThatPassTheMirroredEyeAsFarOffAsTheGapAllowsAndGrazeABoxsOutlineGetTheLoopsHit() {
        // a ray whose line passes the mirrored eye X at a distance, on the side away from a box's
        // outline, comes at a point just inside the outline from a direction just outside it: only
        // the footprint's widening by the angle keeps the box in the ray's cell
        Random random = new Random(11);
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < 2_000; i++) {
            Vector3f corner = new Vector3f((random.nextFloat() * 2 - 1) * 10, 30 + (random.nextFloat() * 2 - 1) * 10,
                    (random.nextFloat() * 2 - 1) * 10);
            objects.add(Box.between(corner, corner.add(new Vector3f(0.01f + random.nextFloat() * 0.5f,
                    0.01f + random.nextFloat() * 0.5f, 0.01f + random.nextFloat() * 0.5f)), new Color(200, 100, 50),
                    Material.DEFAULT));
        }
        objects.add(new Plane(new Vector3f(0, 0, 0), new Vector3f(0, 1, 0), new Color(200, 200, 200), MIRROR));
        double[] x = {3, -12, 2};
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(3, 12, 2), new Vector3f(0, 1, 0), 60);
        Scene scene = new Scene(new Color(0, 0, 0), camera, objects, List.of(LIGHT));
        MirrorGrids grids = MirrorGrids.build(scene, 2048, 2048, 1, 1);
        MirrorGrids.Grid grid = grids.grids().get(0);
        double gap = MirrorGrids.Grid.gap(new Vector3f(3, -12, 2), LightGrids.boxOf(objects));
        Tracer tracer = grids.newTracer(new LinearTracer(scene));

        int served = 0;
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            float[] box = new float[6];
            KnownShapes.putBox(objects.get(random.nextInt(2_000)), box, 0);
            Grazing grazing = Grazing.of(box, x, random); // Q just inside the box's outline seen from X
            double[] q = grazing.q();
            // the line through F, up to the gap off X away from the side, and Q; the origin on it,
            // between the least start and Q
            double[] off = grazing.awayFromSide();
            double by = gap * (0.3 + 0.69 * random.nextDouble());
            double[] f = {by * off[0], by * off[1], by * off[2]};
            double[] along = unit(new double[] {q[0] - f[0], q[1] - f[1], q[2] - f[2]});
            double length = Math.sqrt(dot(q, q));
            double start = 7 + random.nextDouble() * (length - 7.5);
            Vector3f origin = point(x[0] + f[0] + start * along[0], x[1] + f[1] + start * along[1],
                    x[2] + f[2] + start * along[2]);
            Ray ray = new Ray(origin, point(along[0], along[1], along[2]).multiply(0.5f + random.nextFloat() * 3));

            if (check(scene, grids, tracer, ray)) {
                served++;
                hits += scene.nearestHit(ray) != null ? 1 : 0;
            }
        }
        assertThat(grid.cells().entries()).isGreaterThan(2_000);
        assertThat(served).isGreaterThan(15_000);
        assertThat(hits).as("served rays that hit a box").isGreaterThan(5_000);
    }

    @Test
    void aRayLeavingThePointIsServedOnlyIfItsLinePassesWithinTheGapStartsFarEnoughAndShowsOnThePicture() {
        // from 0 along +z at the box from (−1, −1, 9) to (1, 1, 11): 100 pixels span tangents of
        // ±1.01/9, 445.54 pixels a unit of tangent; a gap of 1e-3, rays from 2 units on
        PointFootprint footprint = PointFootprint.leaving(new Vector3f(0, 0, 0), new float[] {-1, -1, 9, 1, 1, 11},
                100, 2, 1e-3);

        // along (0.25, 0, 10): tangent 0.025, pixel 50 + 11.14 across, 50 down
        assertThat(footprint.pixelLeaving(0.125, 0, 5, 0.25, 0, 10)).isEqualTo(50 * 100 + 61);
        assertThat(footprint.pixelLeaving(0.125, 0.0009, 5, 0.25, 0, 10)).as("0.9e-3 beside").isEqualTo(50 * 100 + 61);
        assertThat(footprint.pixelLeaving(0.125, 0.0011, 5, 0.25, 0, 10)).as("1.1e-3 beside").isEqualTo(-1);
        assertThat(footprint.pixelLeaving(0.025, 0, 1, 0.25, 0, 10)).as("starts too near").isEqualTo(-1);
        assertThat(footprint.pixelLeaving(-0.125, 0, -5, 0.25, 0, 10)).as("starts behind").isEqualTo(-1);
        assertThat(footprint.pixelLeaving(0.125, 0, 5, -0.25, 0, -10)).as("runs towards the point").isEqualTo(-1);
        assertThat(footprint.pixelLeaving(2.5, 0, 5, 5, 0, 10)).as("beside the picture").isEqualTo(-1);
        assertThat(footprint.distanceFrom(3, 4, 12)).isEqualTo(13);
    }

    @Test
    void aSphereSeenFromThePointGrowsByItsRoundingOverTheRunFromTheLeastStart() {
        // a sphere of radius 0.5 at 10: its box's farthest corner is √(0.5² + 0.5² + 10.5²) =
        // 10.5238 from the point; rays start 2 on, so they run at most 8.5238 to it, which grows
        // its box by about a thousandth; its footprint reaches tangent 0.5011/9.4989 = 0.052754 and
        // a little more: 50 ∓ 23.50 pixels
        PointFootprint footprint = PointFootprint.leaving(new Vector3f(0, 0, 0), new float[] {-1, -1, 9, 1, 1, 11},
                100, 2, 1e-6);
        Sphere sphere = new Sphere(new Vector3f(0, 0, 10), 0.5f, new Color(1, 2, 3));
        int[] pixels = new int[4];

        float nearest = footprint.putObject(sphere, new float[6], pixels, 0);

        assertThat(pixels).containsExactly(26, 26, 73, 73);
        assertThat(nearest).isLessThan(9.4990f).isGreaterThan(9.4985f);
    }

    @Test
    void theGridServesRaysAsFarFromTheMirroredEyeAsTheShaderLiftsThemOffTheMirror() {
        // the image at (3, −12, 2), the box to 40.5: the lift of a point with coordinates up to 40.5, and a hundredth
        assertThat(MirrorGrids.Grid.gap(new Vector3f(3, -12, 2), new float[] {-1, 2, -3, 4, 40.5f, 6}))
                .isCloseTo((double) Surface.LIFT * 41.5 * 1.01, within(1e-9));
    }

    @Test
    void onlyMirroringPlanesOfALitSceneSeenByThePerspectiveCameraGetAGrid() {
        List<IGeometry> objects = new ArrayList<>(MixedScenes.generate(3, 100).objects());
        objects.removeIf(object -> object instanceof Plane);
        List<IGeometry> withMirrors = new ArrayList<>(objects);
        withMirrors.add(new Plane(new Vector3f(0, -16, 0), new Vector3f(0, 1, 0), new Color(1, 2, 3), MIRROR));
        withMirrors.add(new Plane(new Vector3f(0, 0, -30), new Vector3f(0, 0, 1), new Color(1, 2, 3), MIRROR));
        withMirrors.add(new Plane(new Vector3f(-20, 0, 0), new Vector3f(1, 0, 0), new Color(1, 2, 3), Material.DEFAULT));
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(0, 10, 40), new Vector3f(0, -0.2f, -1), 60);

        assertThat(MirrorGrids.build(new Scene(new Color(0, 0, 0), camera, withMirrors, List.of(LIGHT)), 40, 30, 1, 1)
                .count()).as("two mirrors, one matt plane").isEqualTo(2);
        assertThat(MirrorGrids.build(new Scene(new Color(0, 0, 0), camera, withMirrors, List.of()), 40, 30, 1, 1)
                .count()).as("flat colours").isZero();
        assertThat(MirrorGrids.build(new Scene(new Color(0, 0, 0),
                new OrthographicCamera(new Vector3f(0, 10, 40), new Vector3f(0, 0, -1), 1), withMirrors, List.of(LIGHT)),
                40, 30, 1, 1).count()).as("the orthographic camera").isZero();
        List<IGeometry> eyeInPlane = new ArrayList<>(objects);
        eyeInPlane.add(new Plane(new Vector3f(0, 10, 0), new Vector3f(0, 1, 0), new Color(1, 2, 3), MIRROR));
        assertThat(MirrorGrids.build(new Scene(new Color(0, 0, 0), camera, eyeInPlane, List.of(LIGHT)), 40, 30, 1, 1)
                .count()).as("the eye in the mirror's plane").isZero();
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {31, 32, 33})
    void aShadedPictureWithTheMirrorGridsIsTheBvhsPixelForPixel(long seed) {
        Scene mixed = MixedScenes.shaded(MixedScenes.generate(seed, 250), seed);
        List<IGeometry> objects = new ArrayList<>(mixed.objects());
        objects.removeIf(object -> object instanceof Plane); // which might hide the mirror
        objects.add(new Plane(new Vector3f(0, -16, 0), new Vector3f(0, 1, 0), new Color(200, 200, 200), MIRROR));
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(0, 25, 40), new Vector3f(0, -0.7f, -1), 60);
        Scene scene = new Scene(mixed.ambient(), camera, objects, mixed.lights());
        Bvh bvh = Bvh.build(scene);
        MirrorGrids grids = MirrorGrids.build(scene, 80, 60, 1, 2);
        Function<Tracer, Shader> shaders = tracer -> new WhittedShader(scene, tracer);

        RenderResult withGrids = ParallelRenderer.render(scene.camera(), () -> grids.newTracer(bvh.newTracer()),
                shaders, 80, 60, 2, new RenderProgress());
        RenderResult tree = ParallelRenderer.render(scene.camera(), bvh::newTracer, shaders, 80, 60, 2,
                new RenderProgress());

        assertThat(grids.count()).isPositive();
        assertThat(withGrids.work().answeredBy().get("mirror grids")).isPositive();
        assertThat(withGrids.image().rgb()).isEqualTo(tree.image().rgb());
        assertThat(withGrids.work().secondaryRays()).isEqualTo(tree.work().secondaryRays());
    }
}
