package rtd.geometry;

import static rtd.geometry.TriangleNumbers.CORNERS;
import static rtd.geometry.TriangleNumbers.INWARD;
import static rtd.geometry.TriangleNumbers.INWARD_LENGTH;
import static rtd.geometry.TriangleNumbers.NORMAL;
import static rtd.geometry.TriangleNumbers.NORMAL_SUM;
import static rtd.geometry.TriangleNumbers.SIZE;
import static rtd.geometry.TriangleNumbers.TOLERANCE;
import static rtd.geometry.TriangleNumbers.U;

/**
 * The intersection test of a ray and a triangle, on the triangle's {@value Triangle#NUMBERS}
 * numbers ({@link TriangleNumbers}): it first finds where the ray meets the triangle's plane,
 * then asks on which side of each edge that point lies. Written once: {@link Triangle#intersect}
 * runs it on a triangle's numbers, the engine on the same numbers without making a ray,
 * and {@code --explain} watches it through a {@link TestObserver}.
 *
 * <p>Each side test is a dot product with a vector fixed per edge ({@code n × edge}, in the
 * plane, pointing inwards), so its rounding error, as a distance, is a few units of the last
 * place of the distances involved: a reported hit is never far from the triangle, however thin
 * it is or however flat the ray comes in. A triangle of zero area
 * has {@code n = 0}, no ray meets its plane, and it is never hit.
 */
public final class RayTriangle {

    /**
     * The largest share of the distance run by which the side tests let a hit stray along the
     * ray (see {@link #hit}).
     */
    public static final float ALONG_THE_RAY = 1e-4f;

    private RayTriangle() {
    }

    /**
     * The test on the {@value Triangle#NUMBERS} numbers of {@link Triangle#numbers}, starting
     * at {@code v[at]}: t of the hit, or NaN. Public for the engine, which runs it on a
     * triangle's numbers where they lie.
     *
     * <p>Each side test allows for its own rounding: a point within a few units of the last
     * place of an edge counts as on it. Without that, a ray through an edge that two triangles
     * of a mesh share could slip between them, as each triangle finds its own P and rounds its
     * own way, and the mesh would show cracks. The allowance has three parts: the rounding of
     * the side test itself ({@code (P − p)} times the normal's uncertainty, larger for a thin
     * triangle), of P's coordinates, and of t along the ray, which grows as the ray comes in
     * flatter, up to {@value #ALONG_THE_RAY} of the distance run.
     */
    public static float hit(float[] v, int at, float ox, float oy, float oz, float dx, float dy, float dz,
            TestObserver watch) {
        float facing = (dx * v[at + NORMAL]) + (dy * v[at + NORMAL + 1]) + (dz * v[at + NORMAL + 2]);          // R·n
        float along = ((v[at] - ox) * v[at + NORMAL]) + ((v[at + 1] - oy) * v[at + NORMAL + 1])
                + ((v[at + 2] - oz) * v[at + NORMAL + 2]);                                                   // (p1 − O)·n
        float t = along / facing;
        watch.plane(facing, along, t);
        if (!(t >= 0) || facing == 0 || Float.isInfinite(t)) {
            return Float.NaN;
        }
        float px = ox + dx * t; // as Ray.pointAt rounds it
        float py = oy + dy * t;
        float pz = oz + dz * t;
        float loose = looseness(v, at, px, py, pz, dx, dy, dz, t, facing);
        boolean near = nearTheCorners(v, at, px, py, pz, loose);
        watch.trianglePoint(px, py, pz, loose, near);
        if (!near) {
            return Float.NaN; // the allowances must not stretch a hit far beyond the corners
        }
        return inside(v, at, 0, px, py, pz, loose, watch) && inside(v, at, 1, px, py, pz, loose, watch)
                && inside(v, at, 2, px, py, pz, loose, watch) ? t : Float.NaN;
    }

    /** Whether P lies on the triangle's side of edge {@code k}, up to the rounding allowed. */
    private static boolean inside(float[] v, int at, int k, float px, float py, float pz, float loose, TestObserver watch) {
        float side = side(v, at, k, px, py, pz);
        float allowance = allowance(v, at, k, px, py, pz, loose);
        watch.triangleSide(k, side, allowance);
        return side >= -allowance;
    }

    /**
     * The part of the side tests' allowance that does not depend on the edge: the rounding of
     * P's coordinates, and of t along the ray, which grows as the ray comes in flatter
     * ({@code |R|·|n| / |R·n|}), up to {@value #ALONG_THE_RAY} of the distance run.
     */
    static float looseness(float[] v, int at, float px, float py, float pz, float dx, float dy, float dz, float t,
            float facing) {
        float length = Math.abs(dx) + Math.abs(dy) + Math.abs(dz);
        float along = Math.min(ALONG_THE_RAY, 16 * U * (1 + length * v[at + NORMAL_SUM] / Math.abs(facing)));
        return 16 * U * (Math.abs(px) + Math.abs(py) + Math.abs(pz)) + along * t * length;
    }

    /** Whether P lies within the allowances of the corners' box, on every axis. */
    static boolean nearTheCorners(float[] v, int at, float px, float py, float pz, float loose) {
        float reach = v[at + TOLERANCE] * v[at + SIZE] + loose;
        return near(v, at, 0, px, reach) && near(v, at, 1, py, reach) && near(v, at, 2, pz, reach);
    }

    /**
     * How far below 0 the side test of edge {@code k} (from corner k to the next) may come and
     * still count P as inside: the side test's own rounding, and {@code loose}.
     */
    static float allowance(float[] v, int at, int k, float px, float py, float pz, float loose) {
        int corner = at + CORNERS + 3 * k;
        float fromCorner = Math.abs(px - v[corner]) + Math.abs(py - v[corner + 1]) + Math.abs(pz - v[corner + 2]);
        return (v[at + TOLERANCE] * fromCorner + loose) * v[at + INWARD_LENGTH + k];
    }

    /** {@code (P − corner k)·(n × edge k)}: ≥ 0 when P lies on the triangle's side of edge k. */
    public static float side(float[] v, int at, int k, float px, float py, float pz) {
        return dotFrom(v, at + CORNERS + 3 * k, at + INWARD + 3 * k, px, py, pz);
    }

    /** Whether coordinate {@code axis} of P is within {@code reach} of the corners' range. */
    private static boolean near(float[] v, int at, int axis, float p, float reach) {
        float a = v[at + CORNERS + axis];
        float b = v[at + CORNERS + 3 + axis];
        float c = v[at + CORNERS + 6 + axis];
        return p >= Math.min(a, Math.min(b, c)) - reach && p <= Math.max(a, Math.max(b, c)) + reach;
    }

    /** {@code (P − corner)·inward}, with both given by where they start in {@code v}. */
    private static float dotFrom(float[] v, int corner, int inward, float px, float py, float pz) {
        return ((px - v[corner]) * v[inward]) + ((py - v[corner + 1]) * v[inward + 1]) + ((pz - v[corner + 2]) * v[inward + 2]);
    }
}
