package rtd.io;

/**
 * Splits a face of an OBJ file into triangles (Part II, "Geometry"), as modelling tools do: a
 * convex face as a fan around its first corner, {@code (0,1,2), (0,2,3), …}; any other by ear
 * clipping, so that a concave face (an L, a ring cut open along a slit) is covered where it is
 * and nowhere else.
 *
 * <p>Both work in the face's plane: the one whose normal is Newell's (the sum over the edges of
 * the cross products of consecutive corners), which is the exact normal of a flat face and the
 * best fitting plane of one that is not quite flat. The face is projected onto the world plane
 * most nearly parallel to it, where "convex", "inside" and "an ear" are decided in two
 * dimensions. A face that is not flat is split as its projection is, and each triangle keeps its
 * corners where the file puts them: a surface through the corners, as the tools draw it. A face
 * of no area (its corners on one line) is a fan too; its triangles are never hit.
 *
 * <p>Each face of n corners gives n − 2 triangles, every corner being one of the face's, in the
 * face's turning sense, so that the triangles face where the face does.
 */
final class EarClipping {

    private EarClipping() {
    }

    /**
     * The triangles of the face whose {@code count} corners are the vertices
     * {@code corners[0, count)} of {@code vertices} (x, y, z each): three corner numbers (from 0,
     * in the face) per triangle, in order.
     */
    static int[] triangles(int[] corners, int count, float[] vertices) {
        double[] u = new double[count];
        double[] v = new double[count];
        double sense = project(corners, count, vertices, u, v);
        int[] triangles = new int[3 * (count - 2)];
        if (sense == 0 || isConvex(u, v, count, sense)) {
            for (int k = 1; k + 1 < count; k++) {
                triangles[3 * k - 3] = 0;
                triangles[3 * k - 2] = k;
                triangles[3 * k - 1] = k + 1;
            }
            return triangles;
        }
        clipEars(u, v, count, sense, triangles);
        return triangles;
    }

    /**
     * Writes the corners' coordinates in the plane most nearly parallel to the face into
     * {@code u} and {@code v}, and answers the face's turning sense there: 1, −1, or 0 for a face
     * of no area. The two axes are taken in cyclic order (y, z for x; z, x for y; x, y for z), so
     * that the sign of Newell's normal along the dropped axis is the sense.
     */
    private static double project(int[] corners, int count, float[] vertices, double[] u, double[] v) {
        double nx = 0;
        double ny = 0;
        double nz = 0;
        for (int i = 0; i < count; i++) {
            int a = 3 * corners[i];
            int b = 3 * corners[(i + 1) % count];
            nx += ((double) vertices[a + 1] - vertices[b + 1]) * ((double) vertices[a + 2] + vertices[b + 2]);
            ny += ((double) vertices[a + 2] - vertices[b + 2]) * ((double) vertices[a] + vertices[b]);
            nz += ((double) vertices[a] - vertices[b]) * ((double) vertices[a + 1] + vertices[b + 1]);
        }
        int dropped = Math.abs(nx) >= Math.abs(ny) && Math.abs(nx) >= Math.abs(nz) ? 0 : Math.abs(ny) >= Math.abs(nz) ? 1 : 2;
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
            if (sense * turn(u, v, (i + count - 1) % count, i, (i + 1) % count) < 0) {
                return false;
            }
        }
        return true;
    }

    /**
     * Ear clipping: cuts off, again and again, the first corner (from the face's first on) that
     * turns with the face and whose triangle with its two neighbours holds no other corner of
     * what is left, until one triangle is left. A corner at the same place as one of the
     * triangle's (the two sides of a slit) does not count as inside. Where no such ear is found
     * (a face that crosses itself), the first corner that does not turn against the face is cut
     * off, or else the first corner left.
     */
    private static void clipEars(double[] u, double[] v, int count, double sense, int[] triangles) {
        int[] left = new int[count];
        for (int i = 0; i < count; i++) {
            left[i] = i;
        }
        int written = 0;
        for (int n = count; n > 3; n--) {
            int ear = findEar(u, v, left, n, sense);
            triangles[written++] = left[(ear + n - 1) % n];
            triangles[written++] = left[ear];
            triangles[written++] = left[(ear + 1) % n];
            System.arraycopy(left, ear + 1, left, ear, n - ear - 1);
        }
        triangles[written++] = left[0];
        triangles[written++] = left[1];
        triangles[written] = left[2];
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

    /** Whether the triangle a, b, c holds none of the corners left, on its sides or inside, but at its own corners' places. */
    private static boolean holdsNoCorner(double[] u, double[] v, int[] left, int n, int a, int b, int c) {
        for (int k = 0; k < n; k++) {
            int p = left[k];
            if (samePlace(u, v, p, a) || samePlace(u, v, p, b) || samePlace(u, v, p, c)) {
                continue;
            }
            double ab = turn(u, v, a, b, p);
            double bc = turn(u, v, b, c, p);
            double ca = turn(u, v, c, a, p);
            if ((ab >= 0 && bc >= 0 && ca >= 0) || (ab <= 0 && bc <= 0 && ca <= 0)) {
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
