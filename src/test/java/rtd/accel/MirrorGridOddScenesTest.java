package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;
import static rtd.accel.MirrorGridTest.check;
import static rtd.accel.MirrorGridTest.mirrored;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.render.Tracer;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * The mirror grids in odd scenes (after a review that tried to break them): far from the origin,
 * a mirror at 45° and one of several in a hall of mirrors, objects straddling the mirror, the
 * camera very near it and very far, needles, twins and a mesh whose triangles share edges. Camera
 * rays at points inside their pixels are mirrored up to five times by whatever reflects, and rays
 * are built to pass the mirrored eye as far off as the grid allows, from origins just past the
 * least start to beyond the objects, with directions of any length; each gets the loop's hit.
 */
@DisplayName("The mirror grids answer as the loop does in odd scenes")
class MirrorGridOddScenesTest {

    private static final Material MIRROR = new Material(0.1f, 0.6f, 0.3f, 50, 0.5f, 0, 1);
    private static final Material SHINY = new Material(0.1f, 0.6f, 0.3f, 50, 0.7f, 0, 1);

    static Stream<Arguments> scenes() {
        Random random = new Random(1);
        List<Arguments> scenes = new ArrayList<>();
        List<IGeometry> objects = objects(random, point(1e4, 1e4 + 150, 1e4), 150, 0.05, 30, 600);
        objects.add(mirror(point(1e4, 1e4, 1e4), point(0, 1, 0)));
        scenes.add(Arguments.of("far from the origin", objects, point(1e4 + 100, 1e4 + 3000, 1e4 + 2500),
                point(-0.1, -1, -1)));
        objects = objects(random, point(5, 5, 0), 3, 0.01, 2, 500);
        objects.add(mirror(point(0, 0, 0), point(1, 1, 0.2)));
        scenes.add(Arguments.of("a mirror at 45°", objects, point(12, 14, 9), point(-1, -1, -0.7)));
        objects = objects(random, point(0, 0.3, 0), 0.6, 0.01, 0.9, 400);
        objects.add(mirror(point(0, 0, 0), point(0, 1, 0)));
        scenes.add(Arguments.of("objects straddling the mirror", objects, point(0.5, 8, 6), point(0, -1, -0.7)));
        objects = objects(random, point(0, 0.6, 0), 0.5, 0.01, 0.3, 400);
        objects.add(mirror(point(0, 0, 0), point(0, 1, 0)));
        scenes.add(Arguments.of("the camera near the mirror", objects, point(0.1, 0.25, 0.9), point(0, -0.3, -1)));
        objects = objects(random, point(0, 5, 0), 5, 0.01, 2, 400);
        objects.add(mirror(point(0, 0, 0), point(0, 1, 0)));
        scenes.add(Arguments.of("the camera far from the mirror", objects, point(30, 1000, 40),
                point(-0.03, -1, -0.04)));
        objects = objects(random, point(0, 5, 0), 4, 0.01, 2, 500);
        objects.add(mirror(point(0, 0, 0), point(0, 1, 0)));
        objects.add(2, mirror(point(0, 10, 0), point(0, -1, 0)));
        objects.add(mirror(point(0, 0, -12), point(0, 0, 1)));
        scenes.add(Arguments.of("a hall of mirrors", objects, point(1, 5, 9), point(0, -0.2, -1)));
        objects = terrain(random);
        objects.addAll(objects(random, point(0, 3, 0), 5, 0.05, 1, 300));
        objects.add(mirror(point(0, 0, 0), point(0, 1, 0)));
        objects.add(mirror(point(0, 12, 0), point(0, -1, 0.01)));
        scenes.add(Arguments.of("a mesh under a mirror, and another mirror", objects, point(1, 6, 9),
                point(0, -0.4, -1)));
        return scenes.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void everyServedRayGetsTheLoopsHit(String name, List<IGeometry> objects, Vector3f eye, Vector3f look) {
        Random random = new Random(name.hashCode());
        PerspectiveCamera camera = new PerspectiveCamera(eye, look, 60);
        Scene scene = new Scene(new Color(0, 0, 0), camera, objects,
                List.of(new Light(eye.add(point(1, 5, 1)), new Rgb(1, 1, 1))));
        MirrorGrids grids = MirrorGrids.build(scene, 400, 300, 1, 2);
        Tracer tracer = grids.newTracer(new LinearTracer(scene));

        int served = 0;
        for (int i = 0; i < 6_000; i++) {
            Ray ray = camera.generateRay(random.nextInt(400) + random.nextFloat(), random.nextInt(300) + random.nextFloat(),
                    400, 300);
            Hit hit = scene.nearestHit(ray);
            for (int bounce = 0; bounce < 5 && hit != null && hit.object().material().reflective() > 0; bounce++) {
                ray = mirrored(ray, hit);
                served += check(scene, grids, tracer, ray) ? 1 : 0;
                hit = scene.nearestHit(ray);
            }
        }
        for (MirrorGrid grid : grids.grids()) {
            served += throughTheGap(scene, grids, tracer, grid, eye, random);
        }

        assertThat(grids.count()).isPositive();
        assertThat(served).as("rays the grids served").isGreaterThan(3_000);
    }

    /**
     * Rays whose lines pass X up to 0.999 of the gap off, at a point of a box or just inside its
     * outline seen from X, from origins from just past the least start to beyond the objects; how
     * many the grid served.
     */
    private static int throughTheGap(Scene scene, MirrorGrids grids, Tracer tracer, MirrorGrid grid, Vector3f eye,
            Random random) {
        double[] x = null;
        double least = 0;
        for (IGeometry object : scene.objects()) {
            if (object instanceof Plane plane && plane.material().reflective() > 0) {
                double[] image = imageOf(eye, plane);
                if (grid.footprint.distanceFrom(image[0], image[1], image[2]) == 0) {
                    x = image;
                    least = image[3] / 2;
                }
            }
        }
        List<float[]> boxes = new ArrayList<>();
        for (IGeometry object : scene.objects()) {
            float[] box = new float[6];
            KnownShapes.putBox(object, box, 0);
            if (ImageFootprint.isFinite(box)) {
                boxes.add(box);
            }
        }
        int served = 0;
        for (int i = 0; i < 4_000; i++) {
            float[] box = boxes.get(random.nextInt(boxes.size()));
            double[] q;
            double[] off;
            if (random.nextBoolean()) {
                Grazing grazing = Grazing.of(box, x, random);
                q = grazing.q();
                off = grazing.awayFromSide();
            } else {
                q = new double[] {box[0] + random.nextDouble() * (box[3] - box[0]) - x[0],
                        box[1] + random.nextDouble() * (box[4] - box[1]) - x[1],
                        box[2] + random.nextDouble() * (box[5] - box[2]) - x[2]};
                off = Grazing.unit(Grazing.across(
                        new double[] {random.nextGaussian(), random.nextGaussian(), random.nextGaussian()},
                        Grazing.unit(q)));
            }
            double by = grid.footprint.gap() * (random.nextInt(4) == 0 ? 0.999 : random.nextDouble());
            double[] f = {by * off[0], by * off[1], by * off[2]};
            double[] along = Grazing.unit(new double[] {q[0] - f[0], q[1] - f[1], q[2] - f[2]});
            double length = Math.sqrt(Grazing.dot(q, q));
            double start = switch (random.nextInt(4)) {
                case 0 -> least * (1 + 1e-6);
                case 1 -> least + random.nextDouble() * (length - least);
                case 2 -> length * (0.999 + 0.002 * random.nextDouble());
                default -> least + random.nextDouble() * 2 * length;
            };
            Vector3f origin = Grazing.point(x[0] + f[0] + start * along[0], x[1] + f[1] + start * along[1],
                    x[2] + f[2] + start * along[2]);
            float scale = switch (random.nextInt(4)) {
                case 0 -> 1;
                case 1 -> 1e-3f;
                case 2 -> 1e3f;
                default -> 0.3f + random.nextFloat() * 3;
            };
            served += check(scene, grids, tracer, new Ray(origin,
                    Grazing.point(along[0], along[1], along[2]).multiply(scale))) ? 1 : 0;
        }
        return served;
    }

    /** The mirror image of {@code eye} in {@code mirror} as the grid makes it, and the eye's height over the mirror. */
    private static double[] imageOf(Vector3f eye, Plane mirror) {
        Vector3f normal = mirror.normal();
        double length = Math.sqrt((double) normal.x() * normal.x() + (double) normal.y() * normal.y()
                + (double) normal.z() * normal.z());
        Vector3f point = mirror.point();
        double height = ((eye.x() - (double) point.x()) * normal.x() + (eye.y() - (double) point.y()) * normal.y()
                + (eye.z() - (double) point.z()) * normal.z()) / length;
        double twice = 2 * height / length;
        Vector3f image = Grazing.point(eye.x() - twice * normal.x(), eye.y() - twice * normal.y(),
                eye.z() - twice * normal.z());
        return new double[] {image.x(), image.y(), image.z(), Math.abs(height)};
    }

    /** Random spheres, triangles (a fifth of them needles), boxes and twins around {@code centre}, a third shiny. */
    private static List<IGeometry> objects(Random random, Vector3f centre, double spread, double least, double most,
            int count) {
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            if (!objects.isEmpty() && random.nextInt(15) == 0) {
                objects.add(objects.get(random.nextInt(objects.size()))); // a twin: an exact tie
                continue;
            }
            Vector3f at = Grazing.point(centre.x() + (random.nextDouble() * 2 - 1) * spread,
                    centre.y() + (random.nextDouble() * 2 - 1) * spread,
                    centre.z() + (random.nextDouble() * 2 - 1) * spread);
            float size = (float) (least * Math.pow(most / least, random.nextDouble()));
            Color colour = new Color(random.nextInt(256), random.nextInt(256), random.nextInt(256));
            Material material = random.nextInt(3) == 0 ? SHINY : Material.DEFAULT;
            switch (random.nextInt(3)) {
                case 0 -> objects.add(new Sphere(at, size, colour, material));
                case 1 -> {
                    Vector3f a = at.add(direction(random).multiply(size));
                    Vector3f b = at.add(direction(random).multiply(size));
                    Vector3f c = random.nextInt(5) == 0
                            ? a.add(b.subtract(a).multiply(0.5f)).add(direction(random).multiply(size * 1e-4f))
                            : at.add(direction(random).multiply(size));
                    objects.add(new Triangle(a, b, c, colour, material));
                }
                default -> objects.add(Box.between(at, at.add(Grazing.point(random.nextDouble() * size + size * 1e-3,
                        random.nextDouble() * size + size * 1e-3, random.nextDouble() * size + size * 1e-3)), colour,
                        material));
            }
        }
        return objects;
    }

    /** A terrain of 60 × 60 quads: triangles that share edges and corners. */
    private static List<IGeometry> terrain(Random random) {
        int n = 60;
        float[][] height = new float[n + 1][n + 1];
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                height[i][j] = (float) (1 + 0.8 * Math.sin(i * 0.3) * Math.cos(j * 0.2) + 0.1 * random.nextDouble());
            }
        }
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                Vector3f a = point(i * 0.2 - 6, height[i][j], j * 0.2 - 6);
                Vector3f b = point((i + 1) * 0.2 - 6, height[i + 1][j], j * 0.2 - 6);
                Vector3f c = point(i * 0.2 - 6, height[i][j + 1], (j + 1) * 0.2 - 6);
                Vector3f d = point((i + 1) * 0.2 - 6, height[i + 1][j + 1], (j + 1) * 0.2 - 6);
                Material material = random.nextInt(4) == 0 ? SHINY : Material.DEFAULT;
                objects.add(new Triangle(a, b, c, new Color(1, 2, 3), material));
                objects.add(new Triangle(b, d, c, new Color(1, 2, 3), material));
            }
        }
        return objects;
    }

    private static Plane mirror(Vector3f point, Vector3f normal) {
        return new Plane(point, normal, new Color(200, 200, 200), MIRROR);
    }

    private static Vector3f direction(Random random) {
        return point(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
    }

    private static Vector3f point(double x, double y, double z) {
        return Grazing.point(x, y, z);
    }
}
