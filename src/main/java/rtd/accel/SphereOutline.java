package rtd.accel;

import rtd.geometry.Sphere;
import rtd.math.Vector3f;

/**
 * Where a square's beam of parallel rays stands to a sphere's outline, surely, rounding
 * included: every ray hits the sphere ({@link #everyRayHitsBefore}), or none does
 * ({@link #everyRayMisses}). Not in the paper: two shortcuts of the {@link BeamTracer} for the
 * paper's example, whose picture is mostly squares wholly inside or wholly outside a large
 * sphere. Kept apart from {@link Sphere}, whose intersection test (equations 3.6 to 3.8) is what
 * they reason about, so that the paper's class stays as short as the paper's.
 */
final class SphereOutline {

    private SphereOutline() {
    }

    /**
     * For parallel rays along {@code (dx, dy, dz)} from any origin in the box from
     * {@code lowest} to {@code highest}: a t beyond which none of their hits lies, if
     * {@link Sphere#intersect} surely reports a hit in front of the origin for every one of them;
     * NaN if that is not sure. The beam tracer colours a square of pixels inside the sphere's
     * outline at once with it.
     *
     * <p>Why it is sure, with rounding. As {@link Sphere#bounds} says, the float test hits where an
     * exact test against a radius {@code r'} with {@code |r'² − r²| ≤ δ = 15u·D² + 6u·r²} would
     * (D = |O − M|), so a ray whose line passes the centre at a distance {@code p} with
     * {@code p² ≤ r² − 8δ} gets a discriminant above 0. Its nearer root is ahead when the centre
     * is ahead ({@code R·(O − M) < 0}, here by a thousandth of {@code |R|·D}) and O lies outside
     * ({@code D² ≥ 1.01·r²}, so that {@code 4ac ≥ b²/100}: the root's square root stays a
     * hundredth below {@code |b|}, far more than rounding moves it), and it lies no farther than
     * the point nearest the centre, {@code t = R·(M − O)/R·R}, give or take rounding. Over the
     * box, {@code p²}, D² and that t are largest at corners (a convex and a linear function),
     * and D is smallest at the box's point nearest M; they are computed in double, exactly
     * enough for these margins.
     */
    static double everyRayHitsBefore(Sphere sphere, float[] lowest, float[] highest, float dx, float dy, float dz) {
        Vector3f center = sphere.center();
        double dd = (double) dx * dx + (double) dy * dy + (double) dz * dz;
        double farthestSquared = 0;
        double widestSquared = 0;
        double leastAhead = Double.NEGATIVE_INFINITY;
        double farthestT = Double.NEGATIVE_INFINITY;
        for (int corner = 0; corner < 8; corner++) {
            double mx = ((corner & 1) == 0 ? lowest[0] : highest[0]) - (double) center.x();
            double my = ((corner & 2) == 0 ? lowest[1] : highest[1]) - (double) center.y();
            double mz = ((corner & 4) == 0 ? lowest[2] : highest[2]) - (double) center.z();
            double squared = mx * mx + my * my + mz * mz;
            double along = dx * mx + dy * my + dz * mz;                     // R·(O − M)
            farthestSquared = Math.max(farthestSquared, squared);
            widestSquared = Math.max(widestSquared, squared - along * along / dd);
            leastAhead = Math.max(leastAhead, along);
            farthestT = Math.max(farthestT, -along / dd);
        }
        double rr = sphere.radius() * sphere.radius();                                         // as the test's numbers hold it
        double delta = 0x1p-24 * (15 * farthestSquared + 6 * rr);
        boolean sure = widestSquared <= rr - 8 * delta
                && nearestSquared(center, lowest, highest) >= 1.01 * rr
                && leastAhead <= -1e-3 * Math.sqrt(dd * farthestSquared);
        return sure ? farthestT * (1 + 1e-5) + 1e-5 * Math.sqrt(farthestSquared / dd) : Double.NaN;
    }

    /**
     * Whether {@link Sphere#intersect} surely reports no hit for any ray along {@code (dx, dy, dz)}
     * from an origin in the box from {@code lowest} to {@code highest}, for the sphere of centre
     * {@code (cx, cy, cz)} and squared radius {@code rr} (r·r as the sphere's test computes it).
     * The beam tracer leaves such a sphere out of a square's tests.
     *
     * <p>Why it is sure: a ray whose line passes the centre at a distance {@code p} with
     * {@code p² > r² + 8δ} gets a discriminant below 0 (see {@link #everyRayHitsBefore}), and no
     * origin's line passes nearer than the box's centre's line less the box's half diagonal.
     */
    static boolean everyRayMisses(float cx, float cy, float cz, float rr, float[] lowest, float[] highest,
            float dx, float dy, float dz) {
        double dd = (double) dx * dx + (double) dy * dy + (double) dz * dz;
        double mx = (lowest[0] + (double) highest[0]) / 2 - cx;
        double my = (lowest[1] + (double) highest[1]) / 2 - cy;
        double mz = (lowest[2] + (double) highest[2]) / 2 - cz;
        double along = dx * mx + dy * my + dz * mz;
        double passing = Math.sqrt(Math.max(0, mx * mx + my * my + mz * mz - along * along / dd));
        double hx = (highest[0] - (double) lowest[0]) / 2;
        double hy = (highest[1] - (double) lowest[1]) / 2;
        double hz = (highest[2] - (double) lowest[2]) / 2;
        double halfDiagonal = Math.sqrt(hx * hx + hy * hy + hz * hz);
        double farthest = Math.sqrt(mx * mx + my * my + mz * mz) + halfDiagonal;
        double delta = 0x1p-24 * (15 * farthest * farthest + 6 * rr);
        double nearest = passing - halfDiagonal;
        return nearest > 0 && nearest * nearest > rr + 8 * delta;
    }

    /** The squared distance from the centre to the nearest point of the box. */
    private static double nearestSquared(Vector3f center, float[] lowest, float[] highest) {
        double sum = 0;
        float[] c = {center.x(), center.y(), center.z()};
        for (int k = 0; k < 3; k++) {
            double outside = Math.max(0, Math.max(lowest[k] - (double) c[k], (double) c[k] - highest[k]));
            sum += outside * outside;
        }
        return sum;
    }
}
