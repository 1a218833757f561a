package rtd.geometry;

import rtd.math.Matrix4;
import rtd.math.Ray;

/**
 * Watches an intersection test at work, for {@code --explain}: each shape's test tells it the
 * numbers it computes, as it computes them, so that an explanation shows the very numbers of the
 * picture and not a second computation of them. Every renderer passes {@link #NONE}, which does
 * nothing. A shape that tells nothing is explained by its answer alone.
 */
public interface TestObserver {

    /** Watches nothing: the renderers' observer. */
    TestObserver NONE = new TestObserver() {
    };

    /** A sphere's quadratic (equations 3.5 to 3.8): {@code O − M}, a, b, c and the discriminant {@code b² − 4ac}. */
    default void sphere(float cx, float cy, float cz, float a, float b, float c, float discriminant) {
    }

    /**
     * The roots of a quadratic as they are tried: √D, then
     * {@code (−b − √D)/2a}, then {@code (−b + √D)/2a} (NaN: not needed).
     */
    default void roots(float root, float near, float far) {
    }

    /**
     * A plane's (or a triangle's plane's) {@code t = along / facing}: {@code along = (Q − O)·n}, {@code facing = R·n}.
     */
    default void plane(float facing, float along, float t) {
    }

    /** A box's slab along {@code axis} (0, 1, 2: x, y, z): the ray is between its faces from t0 to t1. */
    default void slab(int axis, float t0, float t1) {
    }

    /** The ray runs parallel to the box's slab along {@code axis}, {@code outside} it or inside it everywhere. */
    default void parallelSlab(int axis, boolean outside) {
    }

    /** Where the ray is in all three slabs: from {@code enter} to {@code exit}. */
    default void slabs(float enter, float exit) {
    }

    /**
     * A triangle's test found the point P on its plane, allows {@code loose} for rounding, and P
     * lies {@code nearTheCorners} (within the corners' box and that allowance) or not.
     */
    default void trianglePoint(float px, float py, float pz, float loose, boolean nearTheCorners) {
    }

    /**
     * A triangle's side test of edge {@code edge} (0, 1, 2):
     * {@code (P − corner)·(n × edge)}, and the rounding it allows.
     */
    default void triangleSide(int edge, float side, float allowance) {
    }

    /**
     * A transformed object's test takes the ray into the object's own space with the inverse of
     * {@code matrix} ({@code M⁻¹O + t·M⁻¹R}); the untransformed shape's own test follows.
     */
    default void transformedRay(Matrix4 matrix, Ray objectRay) {
    }

    /** The shape's test hit at {@code t}, but the world's point lies outside the object's box: float noise, no hit. */
    default void outsideBox(float t) {
    }

    /**
     * A cylinder's or a cone's side (Part III, "More shapes"): the quadratic {@code a·t'² + b·t' + c = 0}
     * solved from the ray's point {@code O' = O + t0·R}, whose roots are where the ray is as far
     * from the axis as the side, and its discriminant.
     */
    default void side(float t0, float a, float b, float c, float discriminant) {
    }

    /**
     * A root of the side's quadratic as the ray's {@code t = t0 + t'},
     * {@code along} the axis from the first end, {@code between} the ends or not.
     */
    default void sideRoot(float t, float along, boolean between) {
    }

    /**
     * A flat cap at end {@code end} (0: the first, 1: the second): the plane's t (NaN: parallel
     * or behind the ray), and the hit point's squared distance from the cap's centre against the
     * cap's squared radius.
     */
    default void cap(int end, float t, float fromCentreSquared, float radiusSquared) {
    }

    /** Which part of a solid with several parts was nearest: "side", "first cap", "second cap", or "none". */
    default void nearestPart(String part, float t) {
    }
}
