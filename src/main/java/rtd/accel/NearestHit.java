package rtd.accel;

import rtd.geometry.Intersection;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Color;

/**
 * One ray, kept as numbers, and the nearest hit found for it so far: the state of the paper's
 * depth test (Listing 4.3) while a tracer visits the leaves of a {@link Bvh} in some order.
 *
 * <p>{@link #testLeaf} runs the paper's intersection test and depth test unchanged: the hit
 * nearest to the origin ({@code |P − O|}) wins, and on a tie the object that comes first in
 * the file. So the order in which leaves are visited does not change the answer; a tracer
 * only must not skip a leaf in which the ray could find a nearer hit ({@link #worthVisiting}).
 *
 * <p>Kept as numbers, and reused from ray to ray, because a {@link Ray} kept in a field
 * would be allocated for every ray.
 */
final class NearestHit {

    /**
     * How much farther than the nearest hit a box may start and still be visited. Distances
     * and box entries round differently; this margin (relative, and relative to the origin's
     * size) keeps a box whose object could tie or win by a rounding error.
     */
    private static final float SKIP_MARGIN = 1e-5f;
    /** The entry of a box the ray misses. */
    static final float MISS = Float.POSITIVE_INFINITY;

    private final Bvh bvh;
    private float ox;
    private float oy;
    private float oz;
    private float dx;
    private float dy;
    private float dz;
    private float dd;
    private float ix;
    private float iy;
    private float iz;
    private float margin;
    private int best;
    private float bestDistance;
    private float skipBeyond;
    private long tests;

    NearestHit(Bvh bvh) {
        this.bvh = bvh;
    }

    /** Starts on a new ray {@code O + t·D}, with no hit yet. */
    void start(float originX, float originY, float originZ, float directionX, float directionY, float directionZ) {
        ox = originX;
        oy = originY;
        oz = originZ;
        dx = directionX;
        dy = directionY;
        dz = directionZ;
        dd = (dx * dx) + (dy * dy) + (dz * dz); // D·D, summed as Vector3f.dot sums
        ix = 1f / dx;
        iy = 1f / dy;
        iz = 1f / dz;
        margin = SKIP_MARGIN * (float) Math.sqrt(ox * ox + oy * oy + oz * oz) / (float) Math.sqrt(dd);
        best = -1;
        bestDistance = Float.POSITIVE_INFINITY;
        skipBeyond = Float.POSITIVE_INFINITY;
    }

    /**
     * The slab test: the ray parameter t at which the ray enters the box of {@code node}, or
     * {@link #MISS}. Negative when the origin lies inside the box.
     */
    float entry(int node) {
        float[] bounds = bvh.bounds;
        int at = 6 * node;
        float x0 = (bounds[at] - ox) * ix;
        float x1 = (bounds[at + 3] - ox) * ix;
        float y0 = (bounds[at + 1] - oy) * iy;
        float y1 = (bounds[at + 4] - oy) * iy;
        float z0 = (bounds[at + 2] - oz) * iz;
        float z1 = (bounds[at + 5] - oz) * iz;
        float enter = FastMath.max(FastMath.max(FastMath.min(x0, x1), FastMath.min(y0, y1)), FastMath.min(z0, z1));
        float exit = FastMath.min(FastMath.min(FastMath.max(x0, x1), FastMath.max(y0, y1)), FastMath.max(z0, z1));
        return enter <= exit && exit >= 0 ? enter : MISS;
    }

    /** Whether the ray enters a box ({@code entry} finite) no farther than the nearest hit allows. */
    boolean worthVisiting(float entry) {
        return entry != MISS && entry <= skipBeyond;
    }

    /** Boxes that the ray enters beyond this t cannot hold a nearer hit (infinite while there is none). */
    float skipBeyond() {
        return skipBeyond;
    }

    /**
     * The paper's intersection test and depth test on a leaf's objects: the nearest hit
     * ({@code |P − O|}) wins, and on a tie the object that comes first in the file.
     */
    void testLeaf(int leaf) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        PackedSpheres spheres = bvh.spheres;
        int[] fileOrder = bvh.fileOrder;
        for (int i = first; i < end; i++) {
            tests++;
            float t;
            float distance;
            if (spheres != null) {
                t = spheres.hit(i, ox, oy, oz, dx, dy, dz, dd);
                distance = PackedSpheres.distance(t, ox, oy, oz, dx, dy, dz);
            } else {
                Vector3f origin = new Vector3f(ox, oy, oz);
                Intersection intersection = bvh.objects[i].intersect(new Ray(origin, new Vector3f(dx, dy, dz)));
                t = intersection.t();
                distance = intersection.contactCoord().subtract(origin).magnitude();
            }
            if (t >= 0 // false for NaN: no hit
                    && (distance < bestDistance
                            || distance == bestDistance && best >= 0 && fileOrder[i] < fileOrder[best])) {
                best = i;
                bestDistance = distance;
                skipBeyond = t + t * SKIP_MARGIN + margin;
            }
        }
    }

    /** The colour of the nearest object hit, or the scene's ambient colour. */
    Color colour() {
        return best < 0 ? bvh.ambient : bvh.objects[best].color();
    }

    /** {@link #colour} as {@code 0xRRGGBB}, from the hierarchy's packed colours: one read from memory, not three. */
    int rgb() {
        return best < 0 ? bvh.ambient.getRGB() : bvh.colours[best];
    }

    /** Intersection tests run for the rays of this object so far. */
    long tests() {
        return tests;
    }
}
