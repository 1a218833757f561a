package rtd.accel;

import rtd.geometry.RayTriangle;
import rtd.geometry.Triangle;
import rtd.math.Vector3f;

/**
 * How little a triangle's test rounds for the rays that leave one point (a perspective camera's
 * eye): far less than for rays from anywhere where they all meet its plane steeply, so that the
 * engine grows its box less for the camera's rays. Not in the paper.
 */
final class TriangleRounding {

    private TriangleRounding() {
    }

    /**
     * The largest share of the distance run by which {@link RayTriangle#hit}'s looseness lets a hit stray along
     * the ray, for the rays that leave the point O = {@code (ox, oy, oz)} with a direction R of
     * {@link KnownShapes#SHORTEST_DIRECTION} ≤ |R|₁ ≤ {@link KnownShapes#LONGEST_DIRECTION} and report
     * a hit on {@code triangle}, whose box ({@link Triangle#bounds}) is
     * {@code box[b .. b+5]}: {@link RayTriangle#ALONG_THE_RAY} at most, much less where every such ray meets
     * the triangle's plane steeply. A perspective camera's rays all leave its eye.
     *
     * <p>Why it holds. A ray O + t·R that reports a hit at t passes Q = O + t·R (exact
     * arithmetic) inside the box grown by what any ray's rounding allows ({@link KnownShapes#rounding},
     * at the farthest such a hit can lie) and by the rounding of the hit point's own coordinates
     * (at t = 0, O itself lies in the box). R points from O to Q, so the ratio
     * {@code |R|₁·|n|₁ / |R·n|} that the looseness grows with is that of Q − O. Over the grown box
     * (Q − O)·n is linear and |Q − O|₁ convex: their extremes lie at its corners. If (Q − O)·n
     * keeps one sign there, the ratio is at most the corners' largest |Q − O|₁ times |n|₁ over their
     * least |(Q − O)·n|. The test works the ratio out in float, from R and n; with |n|₁ between
     * 1e-15 and 1e15 and |R|₁ in its range, no product overflows or falls among the subnormal
     * numbers, and while the ratio is under about 104 (beyond it the looseness is
     * {@link RayTriangle#ALONG_THE_RAY} anyway) the float ratio is within a ten-thousandth of the exact one:
     * 1.01 times it is kept. Otherwise {@link RayTriangle#ALONG_THE_RAY}. The hit then strays at most
     * {@code along·t·|R|₁ ≤ √3·along·L}, which {@link KnownShapes#roundingFrom}'s factor 2 covers.
     */
    static double alongTheRayFrom(Triangle triangle, double ox, double oy, double oz, float[] box, int b) {
        Vector3f n = triangle.planeNormal();
        double normalSum = Math.abs(n.x()) + Math.abs(n.y()) + Math.abs(n.z()); // |n|₁ in float, as the test sums it
        if (!(normalSum >= 1e-15 && normalSum <= 1e15)) {
            return RayTriangle.ALONG_THE_RAY; // the float ratio may overflow, or lose its digits among subnormals
        }
        double anyRay = 2 * RayTriangle.ALONG_THE_RAY; // KnownShapes.rounding of a triangle
        double farthest = 0;
        double largest = Math.max(Math.abs(ox), Math.max(Math.abs(oy), Math.abs(oz)));
        for (int k = 0; k < 3; k++) {
            double o = k == 0 ? ox : k == 1 ? oy : oz;
            double far = Math.max(Math.abs(box[b + k] - o), Math.abs(box[b + 3 + k] - o));
            farthest += far * far;
            largest = Math.max(largest, Math.max(Math.abs(box[b + k]), Math.abs(box[b + 3 + k])));
        }
        // a hit runs L ≤ farthest corner + √3·anyRay·L, and strays anyRay·L; Q strays from P by a few u of their size
        double reach = Math.sqrt(farthest) / (1 - Math.sqrt(3) * (anyRay + KnownShapes.ROUNDING_CONE));
        double grow = anyRay * reach + 8 * 0x1p-24 * (largest + anyRay * reach);
        double nx = n.x();
        double ny = n.y();
        double nz = n.z();
        double leastFacing = Double.POSITIVE_INFINITY;
        double mostFacing = Double.NEGATIVE_INFINITY;
        double longest = 0;
        for (int corner = 0; corner < 8; corner++) {
            double qx = ((corner & 1) == 0 ? box[b] - grow : box[b + 3] + grow) - ox;
            double qy = ((corner & 2) == 0 ? box[b + 1] - grow : box[b + 4] + grow) - oy;
            double qz = ((corner & 4) == 0 ? box[b + 2] - grow : box[b + 5] + grow) - oz;
            double facing = qx * nx + qy * ny + qz * nz;
            leastFacing = Math.min(leastFacing, facing);
            mostFacing = Math.max(mostFacing, facing);
            longest = Math.max(longest, Math.abs(qx) + Math.abs(qy) + Math.abs(qz));
        }
        if (!(leastFacing > 0 || mostFacing < 0)) {
            return RayTriangle.ALONG_THE_RAY; // some of these rays may run along the plane
        }
        double ratio = longest * normalSum / Math.min(Math.abs(leastFacing), Math.abs(mostFacing));
        double along = 16 * 0x1p-24 * (1 + 1.01 * ratio) * (1 + 1e-6);
        // also for an infinite box, whose ratio is NaN
        return along < RayTriangle.ALONG_THE_RAY ? along : RayTriangle.ALONG_THE_RAY;
    }

}
