package rtd.scene;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.OrthographicCamera;
import rtd.image.Color;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.math.Vector3f;
import rtd.testing.ImageComparison;

/**
 * Random scenes with oblique cameras render as the paper's rules say (docs/walkthrough.md, steps
 * 1 to 3): this test carries its own small implementation of those rules, in double precision and
 * without any of rtd's classes in the loop, and compares with the edge tolerance of
 * {@link ImageComparison#EDGE_TOLERANT}.
 */
@DisplayName("Random oblique scenes against an independent reading of the paper's rules")
class SpecReferenceTest {

    private static final int W = 200;
    private static final int H = 150;

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10})
    void matchesTheRulesUpToGrazingPixels(long seed) {
        Random random = new Random(seed);
        double[] dir = {random.nextGaussian(), random.nextGaussian(), random.nextGaussian()};
        if (seed % 5 == 0) {
            dir = new double[] {0, -1, 0}; // straight down: the documented fallback axis
        }
        double[] pos = scale(normalize(dir), -25);
        float zoom = 6 + random.nextFloat() * 6;
        List<IGeometry> spheres = new ArrayList<>();
        for (int i = 0; i < 25; i++) {
            spheres.add(new Sphere(new Vector3f(f(random, 8), f(random, 6), f(random, 8)), 0.5f + random.nextFloat() * 3,
                    new Color(random.nextInt(256), random.nextInt(256), random.nextInt(256))));
        }
        Sphere twin = (Sphere) spheres.get(3);
        spheres.add(new Sphere(twin.center(), twin.radius(), new Color(255, 0, 255))); // a tie: the first must win
        Scene scene = new Scene(new Color(1, 2, 3), new OrthographicCamera(vector(pos), vector(dir), zoom), spheres);

        BufferedImage expected = reference(scene, pos, dir, zoom);
        ImageComparison.Result result = ImageComparison.EDGE_TOLERANT.compare(expected, scene.render(W, H));
        assertThat(result.matches()).as(result.summary()).isTrue();
    }

    /** The paper's steps 1 to 3 (camera ray, intersection, depth test), in double precision. */
    private static BufferedImage reference(Scene scene, double[] pos, double[] dir, double zoom) {
        double[] u = cross(dir, new double[] {0, 1, 0});
        u = length(u) > 0 ? normalize(u) : new double[] {1, 0, 0};
        double[] v = normalize(cross(dir, u));
        BufferedImage image = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double[] origin = add(pos, add(scale(u, (x - W / 2) / zoom), scale(v, (y - H / 2) / zoom)));
                double nearest = Double.POSITIVE_INFINITY;
                int colour = scene.ambient().getRGB();
                for (IGeometry object : scene.objects()) {
                    Sphere s = (Sphere) object;
                    double[] oc = sub(origin, new double[] {s.center().x(), s.center().y(), s.center().z()});
                    double a = dot(dir, dir);
                    double b = 2 * dot(dir, oc);
                    double c = dot(oc, oc) - (double) s.radius() * s.radius();
                    double disc = b * b - 4 * a * c;
                    if (disc < 0) {
                        continue;
                    }
                    double t = (-b - Math.sqrt(disc)) / (2 * a);
                    t = t >= 0 ? t : (-b + Math.sqrt(disc)) / (2 * a);
                    double distance = t * length(dir);
                    if (t >= 0 && distance < nearest) {
                        nearest = distance;
                        colour = s.color().getRGB();
                    }
                }
                image.setRGB(x, y, colour);
            }
        }
        return image;
    }

    private static float f(Random random, float half) {
        return (random.nextFloat() * 2 - 1) * half;
    }

    private static Vector3f vector(double[] a) {
        return new Vector3f((float) a[0], (float) a[1], (float) a[2]);
    }

    private static double[] add(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    private static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static double[] scale(double[] a, double k) {
        return new double[] {a[0] * k, a[1] * k, a[2] * k};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double length(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    private static double[] normalize(double[] a) {
        return scale(a, 1 / length(a));
    }
}
