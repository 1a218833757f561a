package rtd.explain;

import rtd.geometry.Sphere;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * The intersection test of a sphere explained (section 3.2.2, equations 3.5 to 3.8): the same
 * float operations as {@link Sphere#intersect}, in its order, each number on its own line.
 */
final class SphereSteps {

    private SphereSteps() {
    }

    /** Writes the test into {@code text} and returns its t (NaN: no hit). */
    static float explain(Text text, String head, Sphere sphere, Ray ray) {
        Vector3f direction = ray.direction();
        Vector3f centerToOrigin = ray.origin().subtract(sphere.center());
        float a = direction.dot(direction);
        float b = 2 * direction.dot(centerToOrigin);
        float c = centerToOrigin.dot(centerToOrigin) - sphere.radius() * sphere.radius();
        float discriminant = b * b - 4 * a * c;
        text.hanging(head + "sphere: M = " + Numbers.of(sphere.center()) + ", r = " + Numbers.of(sphere.radius()));
        text.line("O − M = " + Numbers.of(centerToOrigin));
        text.line("a = R·R = " + Numbers.of(a) + "   (equation 3.6)");
        text.line("b = 2·R·(O − M) = " + Numbers.of(b) + "   (equation 3.7)");
        text.line("c = (O − M)·(O − M) − r² = " + Numbers.of(c) + "   (equation 3.8)");
        if (!(discriminant >= 0)) {
            text.line("discriminant b² − 4ac = " + Numbers.of(discriminant) + " < 0: no real root, the ray misses");
            return Float.NaN;
        }
        float root = (float) Math.sqrt(discriminant);
        text.line("discriminant b² − 4ac = " + Numbers.of(discriminant) + " ≥ 0, √ = " + Numbers.of(root));
        float near = (-b - root) / (2 * a);
        if (near >= 0) {
            text.line("t = (−b − √)/2a = " + Numbers.of(near) + " ≥ 0: a hit");
            return near;
        }
        float far = (-b + root) / (2 * a);
        if (far >= 0) {
            text.line("t = (−b − √)/2a = " + Numbers.of(near) + " < 0, behind O; t = (−b + √)/2a = " + Numbers.of(far)
                    + " ≥ 0: O is inside, the ray hits the far side");
            return far;
        }
        text.line("t = (−b − √)/2a = " + Numbers.of(near) + " and (−b + √)/2a = " + Numbers.of(far)
                + ": both roots behind O, no hit");
        return Float.NaN;
    }
}
