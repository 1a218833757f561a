package rtd.geometry;

import java.util.List;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A sphere with a centre M, a radius r, a flat colour and a finish (paper, sections 3.2.2 and
 * 4.2.2).
 *
 * <p>{@link #intersect} solves the quadratic equation 3.5 in single precision, exactly in the
 * order of equations 3.6 to 3.8, so that it draws what the paper's program draws.
 */
public record Sphere(Vector3f center, float radius, Color color, Material material) implements IGeometry {

    /** A sphere with the default finish, as the paper's scene file gives one. */
    public Sphere(Vector3f center, float radius, Color color) {
        this(center, radius, color, Material.DEFAULT);
    }

    /**
     * Solves {@code a·t² + b·t + c = 0} (equation 3.5) and returns the smallest root
     * {@code t ≥ 0}: the nearer hit, or the far one when the ray starts inside the sphere.
     */
    @Override
    public Intersection intersect(Ray ray) {
        Vector3f direction = ray.direction();
        Vector3f centerToOrigin = ray.origin().subtract(center);            // O − M
        float a = direction.dot(direction);                                  // equation 3.6
        float b = 2 * direction.dot(centerToOrigin);                        // equation 3.7
        float c = centerToOrigin.dot(centerToOrigin) - radius * radius;      // equation 3.8
        return Intersection.at(ray, smallestRootNotBehind(a, b, b * b - 4 * a * c));
    }

    /**
     * The abc formula: the smaller root {@code (−b − √D) / 2a} if it is {@code ≥ 0}, else the
     * larger one (the ray starts inside the sphere), else NaN (no root, or both behind O).
     * Public for the BVH's packed test of the same equations.
     */
    public static float smallestRootNotBehind(float a, float b, float discriminant) {
        if (!(discriminant >= 0)) {
            return Float.NaN;
        }
        float root = (float) Math.sqrt(discriminant);
        float near = (-b - root) / (2 * a);
        if (near >= 0) {
            return near;
        }
        float far = (-b + root) / (2 * a);
        return far >= 0 ? far : Float.NaN;
    }

    /**
     * For parallel rays along {@code (dx, dy, dz)} from any origin in the box from
     * {@code lowest} to {@code highest}: a t beyond which none of their hits lies, if
     * {@link #intersect} surely reports a hit in front of the origin for every one of them;
     * NaN if that is not sure. Not in the paper: the beam tracer colours a square of pixels
     * inside the sphere's outline at once with it.
     *
     * <p>Why it is sure, with rounding. As {@link #bounds} says, the float test hits where an
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
    public double everyRayHitsBefore(float[] lowest, float[] highest, float dx, float dy, float dz) {
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
        double rr = radius * radius;                                         // as the test's numbers hold it
        double delta = 0x1p-24 * (15 * farthestSquared + 6 * rr);
        boolean sure = widestSquared <= rr - 8 * delta
                && nearestSquared(lowest, highest) >= 1.01 * rr
                && leastAhead <= -1e-3 * Math.sqrt(dd * farthestSquared);
        return sure ? farthestT * (1 + 1e-5) + 1e-5 * Math.sqrt(farthestSquared / dd) : Double.NaN;
    }

    /**
     * Whether {@link #intersect} surely reports no hit for any ray along {@code (dx, dy, dz)}
     * from an origin in the box from {@code lowest} to {@code highest}, for the sphere of centre
     * {@code (cx, cy, cz)} and squared radius {@code rr} (the numbers of {@link #putTestNumbers}).
     * Not in the paper: the beam tracer leaves such a sphere out of a square's tests.
     *
     * <p>Why it is sure: a ray whose line passes the centre at a distance {@code p} with
     * {@code p² > r² + 8δ} gets a discriminant below 0 (see {@link #everyRayHitsBefore}), and no
     * origin's line passes nearer than the box's centre's line less the box's half diagonal.
     */
    public static boolean everyRayMisses(float cx, float cy, float cz, float rr, float[] lowest, float[] highest,
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
    private double nearestSquared(float[] lowest, float[] highest) {
        double sum = 0;
        float[] c = {center.x(), center.y(), center.z()};
        for (int k = 0; k < 3; k++) {
            double outside = Math.max(0, Math.max(lowest[k] - (double) c[k], (double) c[k] - highest[k]));
            sum += outside * outside;
        }
        return sum;
    }

    /** How many numbers {@link #putTestNumbers} writes. */
    public static final int NUMBERS = 4;

    /**
     * Writes the {@value #NUMBERS} numbers {@link #intersect} uses into {@code into} from
     * {@code at}: M's x, y, z and {@code r·r} (equation 3.8), for the BVH's packed copy of the
     * test.
     */
    public void putTestNumbers(float[] into, int at) {
        into[at] = center.x();
        into[at + 1] = center.y();
        into[at + 2] = center.z();
        into[at + 3] = radius * radius;
    }

    /** {@code (P − M) / r}. */
    @Override
    public Vector3f normalAt(Vector3f point) {
        return point.subtract(center).divide(radius);
    }

    /**
     * The sphere's box, widened by how far rounding can move its surface.
     *
     * <p>In {@link #intersect} the discriminant is a difference of two numbers as large as
     * {@code 4|R|²|O − M|²}. Following the standard error bounds of sums and products, the float
     * test hits where an exact test against a sphere of radius {@code r'} would, with
     * {@code r'² ≤ r² + δ} and {@code δ = 15u·D² + 6u·r²} (u the unit roundoff, D = |O − M|;
     * first order, we add a quarter). So the surface moves out by at most
     * {@code min(√δ, δ/2r) + 8u·D}. A hit at t has {@code D ≤ L + r'} with {@code L = t|R|},
     * which bounds that by {@code 1.062e-3·L + 1.74e-3·r} through the root, and by
     * {@code (18.75u/2r)·L² + 2e-6·L + 1e-6·r} through the quotient. The parts that grow with L
     * are the sphere's {@link #rounding}; the rest is grown here, as {@code 2e-3·r}.
     */
    @Override
    public BoundingBox bounds() {
        return BoundingBox.around(radius * (1 + 2e-3), center);
    }

    /** {@link #bounds}, the same numbers, written without making a box. */
    @Override
    public void putBounds(float[] into, int at) {
        BoundingBox.around(radius * (1 + 2e-3), center.x(), center.y(), center.z(), into, at);
    }

    /** {@code 2e-6·L + min(ROUNDING_CONE·L, (18.75u/2r)·L²)}: see {@link #bounds}. */
    @Override
    public Rounding rounding() {
        return new Rounding(2e-6f, (float) (18.75 * 0x1p-24 / (2.0 * radius) * (1 + 1e-3)));
    }

    /** The same shape in the same place, whatever its colour and finish. */
    @Override
    public Object sameTest() {
        return List.of(center, radius);
    }

    @Override
    public String kind() {
        return "sphere";
    }
}
