package rtd.explain;

import java.util.function.Function;
import rtd.geometry.TestObserver;
import rtd.geometry.Transformed;
import rtd.math.Matrix4;
import rtd.math.Ray;

/**
 * The test of a transformed object explained (<i>The Ray Tracer Challenge</i>, chapters 4 and 14): its
 * matrix M, the ray taken into the shape's space ({@code M⁻¹O + t·M⁻¹R}, as {@link Transformed#intersect}
 * tells it), then the shape's own test on that ray, explained as the shape's always is.
 */
final class TransformedSteps implements TestObserver {

    private final Text text;
    private final Function<Text, TestObserver> shapeSteps;
    /** The shape's own steps, made once the ray in its space is known, so that they come after it. */
    private TestObserver inner = TestObserver.NONE;

    TransformedSteps(Text text, String head, Transformed object, Function<Text, TestObserver> shapeSteps) {
        this.text = text;
        this.shapeSteps = shapeSteps;
        text.hanging(head + object.kind() + ", transformed by M = " + matrix(object.matrix()));
    }

    /** The shape's steps (NONE for a shape that tells nothing), for its verdict. */
    TestObserver inner() {
        return inner;
    }

    @Override
    public void transformedRay(Matrix4 matrix, Ray objectRay) {
        text.line("the ray in the shape's own space: M⁻¹O = " + Numbers.of(objectRay.origin()) + ", M⁻¹R = "
                + Numbers.of(objectRay.direction()) + " (not normalised: the same t on both rays)");
        text.in();
        inner = shapeSteps.apply(text);
    }

    @Override
    public void outsideBox(float t) {
        text.line("but P at t = " + Numbers.of(t) + " lies outside the object's box: float's rounding of a far ray, "
                + "no hit");
    }

    /** Closes the shape's steps: the hit point is the world ray's at the same t. */
    void done(float t) {
        text.out();
        if (t >= 0) {
            text.line("P = O + t·R on the world's ray, at the same t = " + Numbers.of(t));
        }
    }

    /** The matrix row by row, each entry to 6 decimals at most: [a b c d; …]. */
    static String matrix(Matrix4 m) {
        StringBuilder text = new StringBuilder("[");
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 4; col++) {
                double v = Math.round(m.get(row, col) * 1e6) / 1e6;
                text.append(col > 0 ? " " : row > 0 ? "; " : "").append(Numbers.of((float) (v == 0 ? 0 : v)));
            }
        }
        return text.append("; 0 0 0 1]").toString();
    }

    @Override
    public void sphere(float cx, float cy, float cz, float a, float b, float c, float discriminant) {
        inner.sphere(cx, cy, cz, a, b, c, discriminant);
    }

    @Override
    public void roots(float root, float near, float far) {
        inner.roots(root, near, far);
    }

    @Override
    public void plane(float facing, float along, float t) {
        inner.plane(facing, along, t);
    }

    @Override
    public void slab(int axis, float t0, float t1) {
        inner.slab(axis, t0, t1);
    }

    @Override
    public void parallelSlab(int axis, boolean outside) {
        inner.parallelSlab(axis, outside);
    }

    @Override
    public void slabs(float enter, float exit) {
        inner.slabs(enter, exit);
    }

    @Override
    public void trianglePoint(float px, float py, float pz, float loose, boolean nearTheCorners) {
        inner.trianglePoint(px, py, pz, loose, nearTheCorners);
    }

    @Override
    public void triangleSide(int edge, float side, float allowance) {
        inner.triangleSide(edge, side, allowance);
    }
}
