package rtd.accel;

import rtd.scene.DepthTest;
import java.util.Arrays;
import rtd.camera.ICamera;
import rtd.geometry.Triangle;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * One thread's room to find the nearest hits of one tile of a {@link HitImage}: the tile's camera
 * rays, as numbers, and each pixel's best hit so far. Each object listed for the tile runs the
 * paper's intersection test on the pixels of its footprint inside the tile (a sphere's and a
 * box's on the copy of their numbers, {@link PackedTests}, a triangle's on its own numbers,
 * {@link Triangle#hit}: the same float operations as their own {@code intersect}), and
 * the depth test ({@link DepthTest}: the nearest hit wins, and on a tie the object that
 * comes first in the file) keeps the winner; the objects without a box are tested on every
 * pixel, as the paper's loop tests them.
 */
final class TileOfHits {

    /**
     * Ints per entry: the object's place in the file; x0, y0, x1, y1 of its pixels; where its
     * copied numbers start (unused for a triangle); kind and test.
     */
    static final int ENTRY = 7;
    private static final int PIXELS = HitImageBuilder.TILE * HitImageBuilder.TILE;

    private final HitImage image;
    private final ICamera camera;
    private final int[] entries;
    private final float[] numbers;
    private final UnboundedObjects unbounded;
    private final float[] ox = new float[PIXELS];
    private final float[] oy = new float[PIXELS];
    private final float[] oz = new float[PIXELS];
    private final float[] dx = new float[PIXELS];
    private final float[] dy = new float[PIXELS];
    private final float[] dz = new float[PIXELS];
    private final float[] dd = new float[PIXELS];
    private final long[] bestKey = new long[PIXELS];
    private final float[] bestT = new float[PIXELS];
    private final float[] bestDistance = new float[PIXELS];
    /** Per kind, per pixel of the tile: the tests run. */
    private final int[][] tests;
    private final float[] ray = new float[6];

    TileOfHits(HitImage image, ICamera camera, int[] entries, float[] numbers) {
        this.image = image;
        this.camera = camera;
        this.entries = entries;
        this.numbers = numbers;
        this.unbounded = new UnboundedObjects(image.unbounded);
        this.tests = new int[image.kindNames.length][PIXELS];
    }

    /** The hits of the pixels {@code [left, right) × [top, bottom)}, whose objects are entries {@code [first, end)}. */
    void draw(int left, int top, int right, int bottom, int first, int end) {
        makeRays(left, top, right, bottom);
        testUnbounded(right - left, bottom - top);
        for (int e = ENTRY * first; e < ENTRY * end; e += ENTRY) {
            testObject(e, left, top);
        }
        store(left, top, right, bottom);
    }

    /** Pixel (x, y) of the tile, its top left (0, 0), row by row at the tile's full width. */
    private static int at(int x, int y) {
        return (y << HitImageBuilder.SHIFT) + x;
    }

    /** Each pixel's ray through its corner, as the camera makes it ({@link ICamera#putRay}), and no hit yet. */
    private void makeRays(int left, int top, int right, int bottom) {
        for (int y = top; y < bottom; y++) {
            for (int x = left; x < right; x++) {
                int p = at(x - left, y - top);
                camera.putRay(x, y, image.width, image.height, ray, 0);
                ox[p] = ray[0];
                oy[p] = ray[1];
                oz[p] = ray[2];
                dx[p] = ray[3];
                dy[p] = ray[4];
                dz[p] = ray[5];
                dd[p] = (ray[3] * ray[3]) + (ray[4] * ray[4]) + (ray[5] * ray[5]); // D·D, as NearestHit sums it
                bestKey[p] = DepthTest.NO_HIT;
                bestT[p] = Float.NaN;
                bestDistance[p] = Float.POSITIVE_INFINITY;
            }
        }
        for (int[] ofKind : tests) {
            Arrays.fill(ofKind, 0);
        }
    }

    /** The objects without a box, on every pixel of a tile {@code width × height}. */
    private void testUnbounded(int width, int height) {
        for (int i = 0; i < unbounded.count(); i++) {
            for (int y = 0; y < height; y++) {
                for (int x = 0; x < width; x++) {
                    int p = at(x, y);
                    float t = unbounded.t(i, ox[p], oy[p], oz[p], dx[p], dy[p], dz[p]);
                    if (t >= 0) { // false for NaN: no hit
                        consider(p, image.unboundedOrder[i], t);
                    }
                }
            }
        }
    }

    /** The object of entry {@code e} on its pixels of the tile whose top left is ({@code left}, {@code top}). */
    private void testObject(int e, int left, int top) {
        int index = entries[e];
        int x0 = entries[e + 1] - left;
        int y0 = entries[e + 2] - top;
        int x1 = entries[e + 3] - left;
        int y1 = entries[e + 4] - top;
        int at = entries[e + 5];
        byte test = (byte) (entries[e + 6] & (1 << PackedTests.BITS) - 1);
        int[] ofKind = tests[entries[e + 6] >> PackedTests.BITS];
        Triangle triangle = test == PackedTests.TRIANGLE ? (Triangle) image.scene.objects().get(index) : null;
        // Each loop runs to an end it stops before (y < rows), not to a last value it reaches
        // (y <= y1): for the second form C2 guards the loop's limit with a check that failed once in
        // every run logged, and sent this method back to the interpreter until C2 compiled it again
        // (a "loop_limit_check" trap, -XX:+LogCompilation; docs/performance.md, the fifteenth round).
        int rows = y1 + 1;
        for (int y = y0; y < rows; y++) {
            int end = at(x1, y) + 1;
            for (int p = at(x0, y); p < end; p++) {
                ofKind[p]++;
                float t = triangle != null ? triangle.hit(ox[p], oy[p], oz[p], dx[p], dy[p], dz[p])
                        : test != PackedTests.OWN_TEST
                        ? PackedTests.t(test, numbers, at, ox[p], oy[p], oz[p], dx[p], dy[p], dz[p], dd[p])
                        : ownTest(index, p);
                if (t >= 0) { // false for NaN: no hit
                    consider(p, index, t);
                }
            }
        }
    }

    /** Any other shape's own {@code intersect}, on pixel {@code p}'s ray. */
    private float ownTest(int index, int p) {
        Ray r = new Ray(new Vector3f(ox[p], oy[p], oz[p]), new Vector3f(dx[p], dy[p], dz[p]));
        return image.scene.objects().get(index).intersect(r).t();
    }

    /** The depth test of Listing 4.3 for pixel {@code p}: as {@link NearestHit}'s. */
    private void consider(int p, int index, float t) {
        float distance = LeafObjects.distance(t, ox[p], oy[p], oz[p], dx[p], dy[p], dz[p]);
        long key = DepthTest.key(distance, index);
        if (key < bestKey[p]) {
            bestKey[p] = key;
            bestT[p] = t;
            bestDistance[p] = distance;
        }
    }

    /** The tile's hits into the image. */
    private void store(int left, int top, int right, int bottom) {
        for (int y = top; y < bottom; y++) {
            for (int x = left; x < right; x++) {
                int p = at(x - left, y - top);
                int pixel = y * image.width + x;
                image.index[pixel] = bestKey[p] != DepthTest.NO_HIT ? (int) bestKey[p] : -1;
                image.t[pixel] = bestT[p];
                image.distance[pixel] = bestDistance[p];
                for (int k = 0; k < tests.length; k++) {
                    image.testsOfKind[k][pixel] = tests[k][p];
                }
            }
        }
    }
}
