package rtd.io;

import java.util.stream.IntStream;

/**
 * Splits a face of an OBJ file into n − 2 triangles that turn as it does (Part II, "Geometry"): a convex face as
 * a fan around its first corner, any other by ear clipping, in the world plane most nearly parallel to its
 * Newell normal.
 */
final class EarClipping {

    /** The corners' coordinates in the plane of the face, and the triangles cut: room kept from face to face. */
    private double[] u = new double[0];
    private double[] v = new double[0];
    private int[] triangles = new int[0];
    /** The turning sense of the face last projected: 1, −1, or 0 for no area. */
    private double sense;

    /**
     * The triangles of the face {@code corners[0, count)}: three corner numbers (from 0, in the face) each, in the
     * first {@code 3·(count − 2)} places of the array answered, which the next face cut here overwrites. A file of
     * a million faces is cut with one set of arrays.
     */
    int[] triangles(int[] corners, int count, float[] vertices) {
        if (!isFan(corners, count, vertices)) {
            clipEars(u, v, count, sense, triangles);
            return triangles;
        }
        for (int k = 1; k + 1 < count; k++) { // a fan around the first corner
            triangles[3 * k - 3] = 0;
            triangles[3 * k - 2] = k;
            triangles[3 * k - 1] = k + 1;
        }
        return triangles;
    }

    /**
     * Whether the face {@code corners[0, count)} is cut as a fan around its first corner: convex, or of no area;
     * projected into {@link #u} and {@link #v}, with its {@link #sense}, for clipping.
     */
    boolean isFan(int[] corners, int count, float[] vertices) {
        if (u.length < count) {
            u = new double[count];
            v = new double[count];
            triangles = new int[3 * (count - 2)];
        }
        sense = project(corners, count, vertices, u, v);
        return sense == 0 || isConvex(u, v, count, sense);
    }

    /**
     * {@link #isFan} of the four corners whose x is {@code vertices[a]}, {@code [b]}, {@code [c]}, {@code [d]},
     * without arrays, for the quads most meshes are made of: Newell's normal summed edge by edge as
     * {@link #project} sums it, and the corners' turns as {@link #turn} computes them in the plane it chooses, so
     * the answer is the general one's to the last bit.
     */
    static boolean isFanQuad(float[] vertices, int a, int b, int c, int d) {
        double nx = newell(vertices, 1, 2, a, b) + newell(vertices, 1, 2, b, c) + newell(vertices, 1, 2, c, d)
                + newell(vertices, 1, 2, d, a);
        double ny = newell(vertices, 2, 0, a, b) + newell(vertices, 2, 0, b, c) + newell(vertices, 2, 0, c, d)
                + newell(vertices, 2, 0, d, a);
        double nz = newell(vertices, 0, 1, a, b) + newell(vertices, 0, 1, b, c) + newell(vertices, 0, 1, c, d)
                + newell(vertices, 0, 1, d, a);
        int dropped = Math.abs(nx) >= Math.abs(ny) && Math.abs(nx) >= Math.abs(nz) ? 0
                : Math.abs(ny) >= Math.abs(nz) ? 1 : 2;
        double sense = Math.signum(dropped == 0 ? nx : dropped == 1 ? ny : nz);
        int iu = dropped == 2 ? 0 : dropped + 1; // (dropped + 1) % 3
        int iv = dropped == 0 ? 2 : dropped - 1; // (dropped + 2) % 3
        return sense == 0 || !(sense * turn(vertices, iu, iv, d, a, b) < 0
                || sense * turn(vertices, iu, iv, a, b, c) < 0 || sense * turn(vertices, iu, iv, b, c, d) < 0
                || sense * turn(vertices, iu, iv, c, d, a) < 0); // as isConvex: no corner turns against the face
    }

    /** The edge p → q's term of Newell's normal along the axis after {@code i} and {@code j}, as {@link #project}'s. */
    private static double newell(float[] vertices, int i, int j, int p, int q) {
        return ((double) vertices[p + i] - vertices[q + i]) * ((double) vertices[p + j] + vertices[q + j]);
    }

    /** {@link #turn} of the corners whose x is {@code vertices[a]}, {@code [b]}, {@code [c]}, in the plane (iu, iv). */
    private static double turn(float[] vertices, int iu, int iv, int a, int b, int c) {
        double ua = vertices[a + iu];
        double va = vertices[a + iv];
        return ((double) vertices[b + iu] - ua) * ((double) vertices[c + iv] - va)
                - ((double) vertices[b + iv] - va) * ((double) vertices[c + iu] - ua);
    }

    /**
     * Writes the corners' coordinates in the plane most nearly parallel to the face into {@code u} and
     * {@code v} (axes in cyclic order, so that Newell's normal along the dropped axis gives the sense), and
     * answers the face's turning sense there: 1, −1, or 0 for no area.
     */
    private static double project(int[] corners, int count, float[] vertices, double[] u, double[] v) {
        double nx = 0;
        double ny = 0;
        double nz = 0;
        for (int i = 0; i < count; i++) {
            int a = 3 * corners[i];
            int b = 3 * corners[i + 1 < count ? i + 1 : 0]; // not (i + 1) % count: a division per corner
            nx += ((double) vertices[a + 1] - vertices[b + 1]) * ((double) vertices[a + 2] + vertices[b + 2]);
            ny += ((double) vertices[a + 2] - vertices[b + 2]) * ((double) vertices[a] + vertices[b]);
            nz += ((double) vertices[a] - vertices[b]) * ((double) vertices[a + 1] + vertices[b + 1]);
        }
        int dropped = Math.abs(nx) >= Math.abs(ny) && Math.abs(nx) >= Math.abs(nz) ? 0
                : Math.abs(ny) >= Math.abs(nz) ? 1 : 2;
        for (int i = 0; i < count; i++) {
            int at = 3 * corners[i];
            u[i] = vertices[at + (dropped + 1) % 3];
            v[i] = vertices[at + (dropped + 2) % 3];
        }
        return Math.signum(dropped == 0 ? nx : dropped == 1 ? ny : nz);
    }

    /** Whether no corner turns against the face's sense (a corner on a straight edge turns neither way). */
    private static boolean isConvex(double[] u, double[] v, int count, double sense) {
        for (int i = 0; i < count; i++) {
            if (sense * turn(u, v, i > 0 ? i - 1 : count - 1, i, i + 1 < count ? i + 1 : 0) < 0) {
                return false;
            }
        }
        return true;
    }

    /**
     * Ear clipping: cuts off, again and again, the first corner that turns with the face and whose triangle
     * holds no other corner left (one at a triangle corner's place, a slit's, does not count). With no such
     * ear (a face that crosses itself), it cuts the first corner that does not turn against the face, or
     * else the first left.
     */
    private static void clipEars(double[] u, double[] v, int count, double sense, int[] triangles) {
        int[] left = IntStream.range(0, count).toArray();
        int written = 0;
        for (int n = count; n > 3; n--) {
            int ear = findEar(u, v, left, n, sense);
            triangles[written++] = left[(ear + n - 1) % n];
            triangles[written++] = left[ear];
            triangles[written++] = left[(ear + 1) % n];
            System.arraycopy(left, ear + 1, left, ear, n - ear - 1);
        }
        System.arraycopy(left, 0, triangles, written, 3);
    }

    /** The position in {@code left[0, n)} of the corner to cut off next. */
    private static int findEar(double[] u, double[] v, int[] left, int n, double sense) {
        int notAgainst = -1;
        for (int k = 0; k < n; k++) {
            int a = left[(k + n - 1) % n];
            int b = left[k];
            int c = left[(k + 1) % n];
            double turn = sense * turn(u, v, a, b, c);
            if (turn > 0 && holdsNoCorner(u, v, left, n, a, b, c)) {
                return k;
            }
            if (turn >= 0 && notAgainst < 0) {
                notAgainst = k;
            }
        }
        return Math.max(notAgainst, 0);
    }

    /** Whether none of the corners left lies in the triangle a, b, c or on its sides, but at its corners' places. */
    private static boolean holdsNoCorner(double[] u, double[] v, int[] left, int n, int a, int b, int c) {
        for (int k = 0; k < n; k++) {
            int p = left[k];
            if (samePlace(u, v, p, a) || samePlace(u, v, p, b) || samePlace(u, v, p, c)) {
                continue;
            }
            double ab = turn(u, v, a, b, p);
            double bc = turn(u, v, b, c, p);
            double ca = turn(u, v, c, a, p);
            if (ab >= 0 && bc >= 0 && ca >= 0 || ab <= 0 && bc <= 0 && ca <= 0) {
                return false;
            }
        }
        return true;
    }

    private static boolean samePlace(double[] u, double[] v, int p, int q) {
        return u[p] == u[q] && v[p] == v[q];
    }

    /** Twice the signed area of the triangle a, b, c: positive where it turns left. */
    private static double turn(double[] u, double[] v, int a, int b, int c) {
        return (u[b] - u[a]) * (v[c] - v[a]) - (v[b] - v[a]) * (u[c] - u[a]);
    }
}
