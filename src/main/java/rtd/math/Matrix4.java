package rtd.math;

import java.util.Arrays;

/**
 * An affine transformation of space, a 4 × 4 matrix whose last row is (0 0 0 1) (<i>The Ray
 * Tracer Challenge</i>, chapters 3, 4 and 14): scalings, rotations and translations, composed.
 *
 * <p>It computes in {@code double}, unlike the paper's {@code float}: a transform is composed of
 * several matrices and inverted once, and rounding every product to float would move the object a
 * little with each step. Points and directions go in and come out as {@link Vector3f}, rounded
 * once. Immutable.
 */
public final class Matrix4 {

    /** The transformation that changes nothing. */
    public static final Matrix4 IDENTITY = new Matrix4(new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});

    /** sin 0°, 90°, 180°, 270°, exactly. */
    private static final double[] QUARTER_SINES = {0, 1, 0, -1};

    /** The top three rows, row by row: {@code m[4·r + c]}. */
    private final double[] m;

    private Matrix4(double[] m) {
        this.m = m;
    }

    /** Scales x, y and z by {@code sx}, {@code sy} and {@code sz}. */
    public static Matrix4 scale(double sx, double sy, double sz) {
        return new Matrix4(new double[] {sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, sz, 0});
    }

    /** Moves every point by (x, y, z). */
    public static Matrix4 translate(double x, double y, double z) {
        return new Matrix4(new double[] {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z});
    }

    /** Turns {@code degrees} about the x axis, right-handed: y towards z. */
    public static Matrix4 rotateX(double degrees) {
        double c = cos(degrees);
        double s = sin(degrees);
        return new Matrix4(new double[] {1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0});
    }

    /** Turns {@code degrees} about the y axis, right-handed: z towards x, so (1, 0, 0) goes to (0, 0, −1) at 90°. */
    public static Matrix4 rotateY(double degrees) {
        double c = cos(degrees);
        double s = sin(degrees);
        return new Matrix4(new double[] {c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0});
    }

    /** Turns {@code degrees} about the z axis, right-handed: x towards y. */
    public static Matrix4 rotateZ(double degrees) {
        double c = cos(degrees);
        double s = sin(degrees);
        return new Matrix4(new double[] {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0});
    }

    /** {@code next · this}: first this transformation, then {@code next}. */
    public Matrix4 then(Matrix4 next) {
        double[] a = next.m;
        double[] r = new double[12];
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 4; col++) {
                double sum = col == 3 ? a[4 * row + 3] : 0; // (0 0 0 1) is this matrix's last row
                for (int k = 0; k < 3; k++) {
                    sum += a[4 * row + k] * m[4 * k + col];
                }
                r[4 * row + col] = sum;
            }
        }
        return new Matrix4(r);
    }

    /** The determinant of the top-left 3 × 3 part: 0 for a transformation that flattens space. */
    public double determinant() {
        return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8])
                + m[2] * (m[4] * m[9] - m[5] * m[8]);
    }

    /** The transformation that undoes this one; the determinant must not be 0. */
    public Matrix4 inverse() {
        double det = determinant();
        double[] r = new double[12];
        // the inverse of the 3 × 3 part by its cofactors, then the translation undone
        r[0] = (m[5] * m[10] - m[6] * m[9]) / det;
        r[1] = (m[2] * m[9] - m[1] * m[10]) / det;
        r[2] = (m[1] * m[6] - m[2] * m[5]) / det;
        r[4] = (m[6] * m[8] - m[4] * m[10]) / det;
        r[5] = (m[0] * m[10] - m[2] * m[8]) / det;
        r[6] = (m[2] * m[4] - m[0] * m[6]) / det;
        r[8] = (m[4] * m[9] - m[5] * m[8]) / det;
        r[9] = (m[1] * m[8] - m[0] * m[9]) / det;
        r[10] = (m[0] * m[5] - m[1] * m[4]) / det;
        for (int row = 0; row < 3; row++) {
            r[4 * row + 3] = -(r[4 * row] * m[3] + r[4 * row + 1] * m[7] + r[4 * row + 2] * m[11]);
        }
        return new Matrix4(r);
    }

    /** The point {@code M·p} (its w is 1: the translation applies). */
    public Vector3f point(Vector3f p) {
        return new Vector3f((float) (row(0, p) + m[3]), (float) (row(1, p) + m[7]), (float) (row(2, p) + m[11]));
    }

    /** The direction {@code M·d} (its w is 0: no translation). */
    public Vector3f direction(Vector3f d) {
        return new Vector3f((float) row(0, d), (float) row(1, d), (float) row(2, d));
    }

    /** {@code Mᵀ·n} of the 3 × 3 part: with the inverse's matrix, how a normal turns ({@code (M⁻¹)ᵀ·n}). */
    public Vector3f transposeDirection(Vector3f n) {
        double x = n.x();
        double y = n.y();
        double z = n.z();
        return new Vector3f((float) (m[0] * x + m[4] * y + m[8] * z), (float) (m[1] * x + m[5] * y + m[9] * z),
                (float) (m[2] * x + m[6] * y + m[10] * z));
    }

    /** The point {@code M·(x, y, z)} in double, for boxes: {@code into[0..2]}. */
    public void point(double x, double y, double z, double[] into) {
        for (int row = 0; row < 3; row++) {
            into[row] = m[4 * row] * x + m[4 * row + 1] * y + m[4 * row + 2] * z + m[4 * row + 3];
        }
    }

    /** The entry at {@code row} and {@code col} (0 to 3 each). */
    public double get(int row, int col) {
        return row == 3 ? (col == 3 ? 1 : 0) : m[4 * row + col];
    }

    private double row(int row, Vector3f v) {
        return m[4 * row] * v.x() + m[4 * row + 1] * (double) v.y() + m[4 * row + 2] * (double) v.z();
    }

    /** The cosine of an angle in degrees; whole quarter turns exactly (cos 90° is 0, not 6e-17). */
    private static double cos(double degrees) {
        return degrees % 90 == 0 ? QUARTER_SINES[quarter(degrees + 90)] : Math.cos(Math.toRadians(degrees));
    }

    /** The sine of an angle in degrees; whole quarter turns exactly. */
    private static double sin(double degrees) {
        return degrees % 90 == 0 ? QUARTER_SINES[quarter(degrees)] : Math.sin(Math.toRadians(degrees));
    }

    /** Which quarter turn, 0 to 3, a whole number of quarter turns ends at. */
    private static int quarter(double degrees) {
        return (int) Math.floorMod((long) (degrees / 90), 4L);
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Matrix4 that && Arrays.equals(m, that.m);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(m);
    }

    @Override
    public String toString() {
        StringBuilder text = new StringBuilder();
        for (int row = 0; row < 4; row++) {
            text.append(row == 0 ? "[" : " [");
            for (int col = 0; col < 4; col++) {
                text.append(col == 0 ? "" : " ").append(get(row, col));
            }
            text.append(']');
        }
        return text.toString();
    }
}
