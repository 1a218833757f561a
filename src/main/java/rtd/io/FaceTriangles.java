package rtd.io;

import java.util.Arrays;

/**
 * The triangles that the faces of an OBJ file become, in the file's order (Part II, "Geometry"): three corners each,
 * vertex indices from 0, and the corners' normals where all three corners of a triangle have one. A face of more than
 * three corners is written as a fan around its first corner; once the file is read, {@link #cutPolygons} cuts the
 * faces that are no fan into their ears ({@link EarClipping}), in the places their fans took. So the loop over the
 * file's lines, which the JIT compiles while a large file is read, does not hold the cutting.
 */
final class FaceTriangles {

    private final EarClipping earClipping = new EarClipping();
    /** The triangles' corners, three per triangle. */
    private int[] corners = new int[3 * 1024];
    /** The normal of each corner of a triangle, or −1 for a triangle with no normals; null while none has. */
    private int[] cornerNormals;
    private int count;
    /** The faces of more than three corners, written as fans: each one's first triangle and its number of corners. */
    private int[] polygons = new int[0];
    private int polygonCount;
    /** A polygon's corners while it is cut: vertex and normal indices. */
    private int[] cutVertices = new int[0];
    private int[] cutNormals = new int[0];

    /**
     * Adds the face of the {@code size} corners {@code vertices[0, size)} and their normals (−1 for none), whose
     * coordinates are {@code coordinates}' x, y, z. A face with normals at some corners only is cut at once: its fan
     * would drop the normals of its triangles that lack one.
     */
    void addFace(int[] vertices, int[] normals, int size, float[] coordinates) {
        if (size > 3 && mixesNormals(normals, size)) {
            int[] triangles = earClipping.triangles(vertices, size, coordinates);
            for (int t = 0; t < 3 * (size - 2); t += 3) {
                add(vertices, normals, triangles[t], triangles[t + 1], triangles[t + 2]);
            }
            return;
        }
        if (size > 3) {
            keepPolygon(size);
        }
        for (int k = 1; k + 1 < size; k++) {
            add(vertices, normals, 0, k, k + 1); // a fan around the first corner, which cutPolygons cuts if it must
        }
    }

    /** Cuts each face of more than three corners that is no fan into its ears, in the places its fan took. */
    void cutPolygons(float[] coordinates) {
        for (int p = 0; p < polygonCount; p++) {
            int first = polygons[2 * p];
            int size = polygons[2 * p + 1];
            for (int k = 0; k < size; k++) { // the fan's triangle j is (0, j + 1, j + 2)
                int at = k == 0 ? 3 * first : k < size - 1 ? 3 * (first + k - 1) + 1 : 3 * (first + size - 3) + 2;
                cutVertices[k] = corners[at];
                cutNormals[k] = cornerNormals == null ? -1 : cornerNormals[at];
            }
            if (!earClipping.isFan(cutVertices, size, coordinates)) {
                int[] triangles = earClipping.triangles(cutVertices, size, coordinates);
                for (int t = 0; t < size - 2; t++) {
                    put(first + t, cutVertices, cutNormals, triangles[3 * t], triangles[3 * t + 1],
                            triangles[3 * t + 2]);
                }
            }
        }
    }

    /** The mesh of these triangles on {@code vertices} and {@code normals} (x, y, z each). */
    ObjMesh mesh(float[] vertices, float[] normals) {
        return new ObjMesh(vertices, normals, corners, cornerNormals, count);
    }

    /** Whether some corners of the face have a normal and others do not. */
    private static boolean mixesNormals(int[] normals, int size) {
        boolean some = false;
        boolean all = true;
        for (int k = 0; k < size; k++) {
            some |= normals[k] >= 0;
            all &= normals[k] >= 0;
        }
        return some && !all;
    }

    /** Notes that a face of {@code size} corners starts at the next triangle, as a fan. */
    private void keepPolygon(int size) {
        if (2 * polygonCount + 2 > polygons.length) {
            polygons = Arrays.copyOf(polygons, Math.max(1024, 2 * polygons.length));
        }
        polygons[2 * polygonCount] = count;
        polygons[2 * polygonCount + 1] = size;
        polygonCount++;
        if (size > cutVertices.length) {
            cutVertices = new int[size];
            cutNormals = new int[size];
        }
    }

    private void add(int[] vertices, int[] normals, int a, int b, int c) {
        if (3 * count + 3 > corners.length) {
            corners = Arrays.copyOf(corners, 2 * corners.length);
            cornerNormals = cornerNormals == null ? null : Arrays.copyOf(cornerNormals, corners.length);
        }
        put(count++, vertices, normals, a, b, c);
    }

    /** Writes the face's corners a, b, c as triangle {@code index}, with their normals if all three have one. */
    private void put(int index, int[] vertices, int[] normals, int a, int b, int c) {
        boolean smooth = normals[a] >= 0 && normals[b] >= 0 && normals[c] >= 0;
        int at = 3 * index;
        corners[at] = vertices[a];
        corners[at + 1] = vertices[b];
        corners[at + 2] = vertices[c];
        if (smooth && cornerNormals == null) { // the first smooth triangle: those before have no normals
            cornerNormals = new int[corners.length];
            Arrays.fill(cornerNormals, -1);
        }
        if (cornerNormals != null) {
            cornerNormals[at] = smooth ? normals[a] : -1;
            cornerNormals[at + 1] = smooth ? normals[b] : -1;
            cornerNormals[at + 2] = smooth ? normals[c] : -1;
        }
    }
}
