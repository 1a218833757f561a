package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

class TriangleOutlineTest {

    private static final Color GREY = new Color(128, 128, 128);

    @Test
    void aTriangleFacingTheCameraTakesTheCellsOfItsPictureNotOfItsRectangle() {
        // Eye at z = 20 looking down −z, 90° across 200 × 100 pixels: f = 100, so a point at
        // depth 20 shows 5 pixels from the middle (100, 50) per unit. The corners (0, 0, 0),
        // (8, 0, 0) and (0, 8, 0) show at (100, 50), (140, 50) and (100, 50 ∓ 40): a right
        // triangle with legs of 40 pixels. Rays through whole pixel positions, one a pixel, meet
        // it at the lattice points of the closed triangle, 1 + 2 + ... + 41 = 861 of them, where its
        // rectangle has 41 × 41 = 1681; the outline grows by about 0.02 pixels, far less than
        // the 0.7 pixels from the hypotenuse to the next lattice points beyond it.
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 90);
        Triangle triangle = new Triangle(new Vector3f(0, 0, 0), new Vector3f(8, 0, 0), new Vector3f(0, 8, 0), GREY, null);
        PerspectiveFootprint footprint = new PerspectiveFootprint(camera, 200, 100, 0);
        float[] box = new float[6];
        int[] rectangle = new int[4];
        footprint.putObject(triangle, box, rectangle, 0);
        float[] outline = new float[TriangleOutline.NUMBERS];
        assertThat(footprint.putOutline(triangle, box, outline, 0)).isTrue();
        assertThat(rectangle).containsAnyOf(100, 140).containsAnyOf(10, 90);
        int inRectangle = 0;
        int inOutline = 0;
        for (int y = rectangle[1]; y <= rectangle[3]; y++) {
            for (int x = rectangle[0]; x <= rectangle[2]; x++) {
                inRectangle++;
                boolean overlaps = TriangleOutline.overlaps(outline, 0, x, y, x, y);
                inOutline += overlaps ? 1 : 0;
                if (hits(camera, triangle, x, y)) {
                    assertThat(overlaps).as("pixel (%d, %d), which the test hits", x, y).isTrue();
                }
            }
        }
        assertThat(inRectangle).isEqualTo(41 * 41);
        assertThat(inOutline).isEqualTo(861);

        // Every pixel of the hypotenuse is hit, each neighbour beyond it is not, as the outline says.
        for (int x = 100; x <= 140; x++) {
            int below = 50 + (140 - x); // where y runs down the picture and the triangle lies below 50
            int above = 50 - (140 - x);
            int onEdge = hits(camera, triangle, x, below) ? below : above;
            assertThat(hits(camera, triangle, x, onEdge)).as("pixel (%d, %d) on the hypotenuse", x, onEdge).isTrue();
            assertThat(TriangleOutline.overlaps(outline, 0, x, onEdge, x, onEdge)).isTrue();
            int beyond = onEdge == below ? onEdge + 1 : onEdge - 1;
            if (x < 140) {
                assertThat(hits(camera, triangle, x + 1, beyond)).isFalse();
                assertThat(TriangleOutline.overlaps(outline, 0, x + 1, beyond, x + 1, beyond))
                        .as("pixel (%d, %d) beyond it", x + 1, beyond).isFalse();
            }
        }
    }

    private static boolean hits(PerspectiveCamera camera, Triangle triangle, int x, int y) {
        return triangle.intersect(camera.generateRay(x, y, 200, 100)).t() >= 0;
    }

    @Test
    void aNeedleASideViewAndATriangleAroundTheEyeHaveNoOutline() {
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 90);
        PerspectiveFootprint footprint = new PerspectiveFootprint(camera, 200, 100, 0);
        assertThat(outline(footprint, new Triangle(new Vector3f(0, 0, 0), new Vector3f(8, 0, 0), new Vector3f(0, 8, 0),
                GREY, null))).as("facing the eye").isTrue();
        assertThat(outline(footprint, new Triangle(new Vector3f(0, 0, 0), new Vector3f(8, 0, 0),
                new Vector3f(8, 0.01f, 0), GREY, null))).as("a needle: its corner of 0.07°").isFalse();
        assertThat(outline(footprint, new Triangle(new Vector3f(0, -1, 0), new Vector3f(0, 1, 0), new Vector3f(0, 0, -5),
                GREY, null))).as("in a plane through the eye").isFalse();
        assertThat(outline(footprint, new Triangle(new Vector3f(-1, -1, 19), new Vector3f(1, -1, 19),
                new Vector3f(0, 1, 21), GREY, null))).as("around the eye").isFalse();
    }

    private static boolean outline(PerspectiveFootprint footprint, Triangle triangle) {
        float[] box = new float[6];
        int[] pixels = new int[4];
        footprint.putObject(triangle, box, pixels, 0);
        return footprint.putOutline(triangle, box, new float[TriangleOutline.NUMBERS], 0);
    }

    /**
     * Rays aimed at random points of the edges, give or take a hundredth of a pixel, through
     * random cameras at random sub-pixel offsets: wherever the test lets one hit, its pixel's cell
     * overlaps the outline. Many of them hit though they pass beside the exact picture of the
     * triangle (the test's allowances), so an outline without its growth fails here.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void everyRayTheTestLetsHitATriangleHasItsPixelInTheOutline(long seed) {
        Random random = new Random(seed);
        int width = 160;
        int height = 90;
        int accepted = 0;
        int outsideThePicture = 0;
        int outlined = 0;
        for (int round = 0; round < 300; round++) {
            Triangle triangle = randomTriangle(random);
            PerspectiveCamera camera = cameraFacing(triangle, random);
            float latestOffset = random.nextInt(4) == 0 ? 0 : 0.875f;
            PerspectiveFootprint footprint = new PerspectiveFootprint(camera, width, height, latestOffset);
            float[] box = new float[6];
            int[] pixels = new int[4];
            float nearest = footprint.putObject(triangle, box, pixels, 0);
            float[] outline = new float[TriangleOutline.NUMBERS];
            if (nearest != nearest || !footprint.putOutline(triangle, box, outline, 0)) {
                continue;
            }
            outlined++;
            double[][] picture = new double[3][];
            for (int k = 0; k < 3; k++) {
                picture[k] = pictureOf(camera, triangle.corner(k), width, height);
            }
            for (int ray = 0; ray < 200; ray++) {
                int k = random.nextInt(3);
                double s = random.nextDouble();
                double aimX = picture[k][0] + s * (picture[(k + 1) % 3][0] - picture[k][0])
                        + (random.nextDouble() - 0.5) * 0.02;
                double aimY = picture[k][1] + s * (picture[(k + 1) % 3][1] - picture[k][1])
                        + (random.nextDouble() - 0.5) * 0.02;
                // the ray at the aim, which pixel (px, py) casts if it lies up to latestOffset into it
                float x = latestOffset == 0 ? Math.round(aimX) : (float) aimX;
                float y = latestOffset == 0 ? Math.round(aimY) : (float) aimY;
                int px = (int) Math.floor(x);
                int py = (int) Math.floor(y);
                if (px < 0 || py < 0 || px >= width || py >= height || x - px > latestOffset || y - py > latestOffset) {
                    continue;
                }
                Ray cameraRay = camera.generateRay(x, y, width, height);
                if (!(triangle.intersect(cameraRay).t() >= 0)) {
                    continue;
                }
                accepted++;
                if (!inside(picture, x, y)) {
                    outsideThePicture++;
                }
                String what = "triangle " + triangle.sameTest() + ", camera " + camera.position() + " " + camera.forward()
                        + ", ray at (" + x + ", " + y + ")";
                assertThat(px).as(what).isBetween(pixels[0], pixels[2]);
                assertThat(py).as(what).isBetween(pixels[1], pixels[3]);
                assertThat(TriangleOutline.overlaps(outline, 0, px, py, px + latestOffset, py + latestOffset)).as(what)
                        .isTrue();
            }
        }
        assertThat(outlined).as("triangles outlined").isGreaterThan(150);
        assertThat(accepted).as("rays hit").isGreaterThan(10_000);
        assertThat(outsideThePicture).as("rays hit beside the exact picture").isGreaterThan(100);
    }

    /** A triangle of random shape, size and place, some far from the world's origin. */
    private static Triangle randomTriangle(Random random) {
        double size = Math.pow(10, -3 + 4 * random.nextDouble());
        double far = random.nextInt(4) == 0 ? 1000 : 1;
        Vector3f middle = new Vector3f((float) (far * (random.nextDouble() - 0.5)), (float) (far * (random.nextDouble() - 0.5)),
                (float) (far * (random.nextDouble() - 0.5)));
        Vector3f[] corners = new Vector3f[3];
        for (int k = 0; k < 3; k++) {
            corners[k] = middle.add(new Vector3f((float) (size * random.nextGaussian()), (float) (size * random.nextGaussian()),
                    (float) (size * random.nextGaussian())));
        }
        return new Triangle(corners[0], corners[1], corners[2], GREY, null);
    }

    /** A camera from 1 to 60 sizes of the triangle away, looking roughly at it, from any side. */
    private static PerspectiveCamera cameraFacing(Triangle triangle, Random random) {
        Vector3f middle = triangle.corner(0).add(triangle.corner(1)).add(triangle.corner(2)).multiply(1 / 3f);
        float size = triangle.corner(1).subtract(triangle.corner(0)).magnitude();
        Vector3f away = new Vector3f((float) random.nextGaussian(), (float) random.nextGaussian(), (float) random.nextGaussian())
                .normalize().multiply(size * (1 + 59 * random.nextFloat()));
        Vector3f eye = middle.add(away);
        Vector3f look = middle.subtract(eye).add(new Vector3f((float) random.nextGaussian(), (float) random.nextGaussian(),
                (float) random.nextGaussian()).multiply(size * 0.3f));
        return new PerspectiveCamera(eye, look, 10 + random.nextFloat() * 140);
    }

    /** Where a point shows on the picture, in pixels, in double. */
    private static double[] pictureOf(PerspectiveCamera camera, Vector3f point, int width, int height) {
        Vector3f relative = point.subtract(camera.position());
        double depth = dot(relative, camera.forward());
        double f = camera.focalLength(width);
        return new double[] {width / 2 + f * dot(relative, camera.widthVector()) / depth,
                height / 2 + f * dot(relative, camera.heightVector()) / depth};
    }

    private static double dot(Vector3f a, Vector3f b) {
        return (double) a.x() * b.x() + (double) a.y() * b.y() + (double) a.z() * b.z();
    }

    /** Whether (x, y) lies in the triangle of the three pictures, exactly as double computes it. */
    private static boolean inside(double[][] picture, double x, double y) {
        double sign = 0;
        for (int k = 0; k < 3; k++) {
            double[] a = picture[k];
            double[] b = picture[(k + 1) % 3];
            double side = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
            if (side != 0) {
                if (sign != 0 && Math.signum(side) != sign) {
                    return false;
                }
                sign = Math.signum(side);
            }
        }
        return true;
    }
}
