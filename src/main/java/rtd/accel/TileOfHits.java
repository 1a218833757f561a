package rtd.accel;

import java.util.Arrays;
import rtd.camera.ICamera;
import rtd.geometry.Sphere;
import rtd.geometry.TestObserver;
import rtd.scene.DepthTest;

/**
 * One thread's room to find the nearest hits of one tile of a {@link HitImage}: the tile's camera rays as numbers, made
 * as the renderer makes them ({@link ICamera#putRay}, as {@link rtd.render.RayBundle} calls it), and each pixel's
 * nearest hit so far. Each object listed for the tile runs
 * the paper's intersection test on the pixels of its footprint inside the tile, as a {@link NearestHit} runs it (the
 * shape's own kernel, {@link LeafObjects#t}), and the depth test ({@link DepthTest#key}: the nearest hit wins, and on
 * a tie the object that comes first in the file) keeps the winner; the objects without a box are tested on every
 * pixel, as the paper's loop tests them.
 */
final class TileOfHits {

    private static final int PIXELS = HitImage.TILE * HitImage.TILE;

    private final HitImage image;
    private final ViewGrid tiles;
    private final LeafObjects leaves;
    private final int[] footprints;
    private final UnboundedObjects unbounded;
    private final int[] unboundedOrder;
    private final int kinds;
    private final float[] ray = new float[6];
    // the rays in arrays of the tile's own, not read through a RayBundle: its methods, called between tests that the
    // JIT does not inline, would load its arrays anew for every test
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
    /**
     * Per pixel of the tile, per kind: the tests run, kept as differences along rows ({@link #count}) until the tile is
     * stored, when a running sum turns them into counts: two writes a row of an object, not one a pixel.
     */
    private final int[] tests;

    /** A room for {@code image}'s tiles, whose objects {@code tiles} lists, of {@code footprints} in leaf order. */
    TileOfHits(HitImage image, ViewGrid tiles, int[] footprints) {
        this.image = image;
        this.tiles = tiles;
        this.leaves = tiles.objects.leaves;
        this.footprints = footprints;
        this.unbounded = new UnboundedObjects(tiles.objects.unbounded);
        this.unboundedOrder = tiles.objects.unboundedOrder;
        this.kinds = image.kindNames.length;
        this.tests = new int[HitImage.TILE * (HitImage.TILE + 1) * kinds];
    }

    /** The hits of the tile whose top left pixel is ({@code left}, {@code top}), into the image. */
    void draw(int left, int top) {
        int right = Math.min(image.width, left + HitImage.TILE);
        int bottom = Math.min(image.height, top + HitImage.TILE);
        int count = makeRays(left, top, right, bottom);
        Arrays.fill(tests, 0);
        for (int u = 0; u < unbounded.count(); u++) {
            for (int i = 0; i < count; i++) {
                float t = unbounded.t(u, ox[i], oy[i], oz[i], dx[i], dy[i], dz[i]);
                if (t >= 0) { // false for NaN: no hit
                    consider(i, unboundedOrder[u], t);
                }
            }
        }
        int cell = tiles.cellOf(left, top);
        for (int k = tiles.cellStart[cell]; k < tiles.cellStart[cell + 1]; k++) {
            test(tiles.places[k], left, top, right, bottom);
        }
        store(left, top, right, bottom);
    }

    /** The rays of pixels {@code [left, right) × [top, bottom)}, row by row, and no hit yet; answers how many. */
    private int makeRays(int left, int top, int right, int bottom) {
        int i = 0;
        for (int y = top; y < bottom; y++) {
            for (int x = left; x < right; x++, i++) {
                image.scene.camera().putRay(x, y, image.width, image.height, ray, 0);
                ox[i] = ray[0];
                oy[i] = ray[1];
                oz[i] = ray[2];
                dx[i] = ray[3];
                dy[i] = ray[4];
                dz[i] = ray[5];
                dd[i] = (ray[3] * ray[3]) + (ray[4] * ray[4]) + (ray[5] * ray[5]); // D·D, summed as NearestHit sums it
                bestKey[i] = DepthTest.NO_HIT;
                bestT[i] = Float.NaN;
                bestDistance[i] = Float.POSITIVE_INFINITY;
            }
        }
        return i;
    }

    /** The object at {@code place} in leaf order on its pixels of the tile {@code [left, right) × [top, bottom)}. */
    private void test(int place, int left, int top, int right, int bottom) {
        int index = leaves.fileOrder[place];
        int at = 4 * place;
        int across = right - left;
        int x0 = Math.max(footprints[at], left) - left;
        int x1 = Math.min(footprints[at + 2] + 1, right) - left; // the first pixel beyond, as each loop's end
        int y0 = Math.max(footprints[at + 1], top) - top;
        int y1 = Math.min(footprints[at + 3] + 1, bottom) - top;
        count(leaves.kinds[place], x0, x1, y0, y1);
        int sphere = leaves.sphereAt(place);
        if (sphere >= 0) {
            testSphere(leaves.numbers, sphere, index, across, x0, x1, y0, y1);
            return;
        }
        for (int y = y0; y < y1; y++) {
            int end = y * across + x1;
            for (int i = y * across + x0; i < end; i++) {
                float t = leaves.t(place, ox[i], oy[i], oz[i], dx[i], dy[i], dz[i], dd[i]);
                if (t >= 0) { // false for NaN: no hit
                    consider(i, index, t);
                }
            }
        }
    }

    /**
     * {@link #test} for a sphere whose centre and radius lie at {@code numbers[at]}: the numbers are read once for
     * all its pixels, and each pixel's ray runs {@link Sphere#hit}, as {@link PackedTests} runs it.
     */
    private void testSphere(float[] numbers, int at, int index, int across, int x0, int x1, int y0, int y1) {
        float mx = numbers[at];
        float my = numbers[at + 1];
        float mz = numbers[at + 2];
        float r = numbers[at + 3];
        for (int y = y0; y < y1; y++) {
            int end = y * across + x1;
            for (int i = y * across + x0; i < end; i++) {
                float t = Sphere.hit(mx, my, mz, r, ox[i], oy[i], oz[i], dx[i], dy[i], dz[i], TestObserver.NONE);
                if (t >= 0) { // false for NaN: no hit
                    consider(i, index, t);
                }
            }
        }
    }

    /**
     * One test of kind {@code kind} on each pixel of {@code [x0, x1) × [y0, y1)}, as differences along each row of a
     * grid one wider than the tile: a row's running sum gives each pixel its count ({@link #store}).
     */
    private void count(int kind, int x0, int x1, int y0, int y1) {
        for (int y = y0; y < y1; y++) {
            tests[(y * (HitImage.TILE + 1) + x0) * kinds + kind]++;
            tests[(y * (HitImage.TILE + 1) + x1) * kinds + kind]--;
        }
    }

    /** The depth test of Listing 4.3 for pixel {@code i} of the tile, as {@link NearestHit}'s. */
    private void consider(int i, int index, float t) {
        float distance = LeafObjects.distance(t, ox[i], oy[i], oz[i], dx[i], dy[i], dz[i]);
        long key = DepthTest.key(distance, index);
        if (key < bestKey[i]) {
            bestKey[i] = key;
            bestT[i] = t;
            bestDistance[i] = distance;
        }
    }

    /** The tile's hits, of the pixels {@code [left, right) × [top, bottom)}, into the image. */
    private void store(int left, int top, int right, int bottom) {
        for (int y = top, i = 0; y < bottom; y++) {
            int row = (y - top) * (HitImage.TILE + 1) * kinds;
            for (int x = left; x < right; x++, i++) {
                int pixel = y * image.width + x;
                image.index[pixel] = bestKey[i] != DepthTest.NO_HIT ? (int) bestKey[i] : -1;
                image.t[pixel] = bestT[i];
                image.distance[pixel] = bestDistance[i];
                int at = row + (x - left) * kinds;
                int all = unbounded.count();
                for (int k = 0; k < kinds; k++) { // the row's running sum: this pixel's count
                    tests[at + k] += x > left ? tests[at + k - kinds] : 0;
                    if (image.tests != null) {
                        image.tests[pixel * kinds + k] = tests[at + k];
                    }
                    all += tests[at + k];
                }
                image.rayTests[pixel] = all;
            }
        }
    }
}
