package rtd.geometry;

import rtd.math.Vector3f;

/**
 * What an intersection test found (paper, section 4.2.2): whether the ray hit the object, and
 * if so where.
 *
 * @param happened     whether the ray hits the object at some {@code t ≥ 0}
 * @param t            the ray parameter of the hit, {@code P = O + t·R} (equation 3.1); NaN on a miss
 * @param contactCoord the hit point P, the paper's name for it; meaningless on a miss
 */
public record Intersection(boolean happened, float t, Vector3f contactCoord) {
}
