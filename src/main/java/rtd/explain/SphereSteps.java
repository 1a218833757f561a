package rtd.explain;

import rtd.geometry.Sphere;
import rtd.geometry.TestObserver;
import rtd.math.Vector3f;

/**
 * The intersection test of a sphere explained (section 3.2.2, equations 3.5 to 3.8): the numbers
 * {@link Sphere#hit} tells as it computes them, each on its own line.
 */
final class SphereSteps implements TestObserver {

    private final Text text;
    private float discriminant;

    SphereSteps(Text text, String head, Sphere sphere) {
        this.text = text;
        text.hanging(head + "sphere: M = " + Numbers.of(sphere.center()) + ", r = " + Numbers.of(sphere.radius()));
    }

    @Override
    public void sphere(float cx, float cy, float cz, float a, float b, float c, float discriminant) {
        this.discriminant = discriminant;
        text.line("O − M = " + Numbers.of(new Vector3f(cx, cy, cz)));
        text.line("a = R·R = " + Numbers.of(a) + "   (equation 3.6)");
        text.line("b = 2·R·(O − M) = " + Numbers.of(b) + "   (equation 3.7)");
        text.line("c = (O − M)·(O − M) − r² = " + Numbers.of(c) + "   (equation 3.8)");
        if (!(discriminant >= 0)) {
            text.line("discriminant b² − 4ac = " + Numbers.of(discriminant) + " < 0: no real root, the ray misses");
        }
    }

    @Override
    public void roots(float root, float near, float far) {
        text.line("discriminant b² − 4ac = " + Numbers.of(discriminant) + " ≥ 0, √ = " + Numbers.of(root));
        if (near >= 0) {
            text.line("t = (−b − √)/2a = " + Numbers.of(near) + " ≥ 0: a hit");
        } else if (far >= 0) {
            text.line("t = (−b − √)/2a = " + Numbers.of(near) + " < 0, behind O; t = (−b + √)/2a = " + Numbers.of(far)
                    + " ≥ 0: O is inside, the ray hits the far side");
        } else {
            text.line("t = (−b − √)/2a = " + Numbers.of(near) + " and (−b + √)/2a = " + Numbers.of(far)
                    + ": both roots behind O, no hit");
        }
    }
}
