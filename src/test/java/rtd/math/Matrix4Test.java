package rtd.math;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

@DisplayName("Transformations as matrices (The Ray Tracer Challenge, chapters 4 and 14)")
class Matrix4Test {

    private static final Vector3f X = new Vector3f(1, 0, 0);

    @Test
    void rotatingAboutYByAQuarterTurnTakesXToMinusZ() {
        assertThat(Matrix4.rotateY(90).point(X)).isEqualTo(new Vector3f(0, 0, -1));
    }

    @Test
    void rotatingAboutXTakesYToZAndAboutZTakesXToY() {
        assertThat(Matrix4.rotateX(90).direction(new Vector3f(0, 1, 0))).isEqualTo(new Vector3f(0, 0, 1));
        assertThat(Matrix4.rotateZ(90).direction(X)).isEqualTo(new Vector3f(0, 1, 0));
    }

    @Test
    void rotatingByThirtyDegreesFollowsTheFormula() {
        // rotate_y 30: (x, y, z) -> (x cos a + z sin a, y, -x sin a + z cos a); (1|0|0) -> (0.8660254|0|-0.5)
        Vector3f p = Matrix4.rotateY(30).point(X);
        assertThat(p.x()).isCloseTo(0.8660254f, within(1e-7f));
        assertThat(p.z()).isCloseTo(-0.5f, within(1e-7f));
    }

    @Test
    void operationsApplyInTheOrderWritten() {
        // first scale by 2, then move by 1 in x: (1|0|0) -> (2|0|0) -> (3|0|0); the other order gives 4
        Matrix4 scaleThenMove = Matrix4.scale(2, 2, 2).then(Matrix4.translate(1, 0, 0));
        Matrix4 moveThenScale = Matrix4.translate(1, 0, 0).then(Matrix4.scale(2, 2, 2));
        assertThat(scaleThenMove.point(X)).isEqualTo(new Vector3f(3, 0, 0));
        assertThat(moveThenScale.point(X)).isEqualTo(new Vector3f(4, 0, 0));
    }

    @Test
    void aDirectionIsNotMovedByATranslation() {
        assertThat(Matrix4.translate(5, 6, 7).direction(X)).isEqualTo(X);
    }

    @Test
    void theInverseUndoesTheTransformation() {
        Matrix4 m = Matrix4.scale(2, 3, 4).then(Matrix4.rotateY(30)).then(Matrix4.translate(1, 2, 3));
        Vector3f p = new Vector3f(0.5f, -1, 2);
        Vector3f back = m.inverse().point(m.point(p));
        assertThat(back.x()).isCloseTo(0.5f, within(1e-6f));
        assertThat(back.y()).isCloseTo(-1f, within(1e-6f));
        assertThat(back.z()).isCloseTo(2f, within(1e-6f));
        // scale 2|3|4: the inverse scales by 1/2, 1/3, 1/4
        assertThat(Matrix4.scale(2, 3, 4).inverse().get(1, 1)).isEqualTo(1.0 / 3);
    }

    @Test
    void theDeterminantOfAScaleIsTheProductOfItsFactors() {
        assertThat(Matrix4.scale(2, 3, 4).determinant()).isEqualTo(24);
        assertThat(Matrix4.scale(1, 0, 1).determinant()).isZero();
    }
}
