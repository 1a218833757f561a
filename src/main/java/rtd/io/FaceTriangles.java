package rtd.io;

import java.util.Arrays;

/**
 * The triangles that the faces of an OBJ file become, in the file's order (Part II, "Geometry"): three corners each,
 * vertex indices from 0, and the corners' normals where all three corners of a triangle have one. A face of more than
 * three corners becomes a fan around its first corner if it is convex, else its ears ({@link EarClipping}).
 */
final class FaceTriangles {

    private final EarClipping earClipping = new EarClipping();
    /** The triangles' corners, three per triangle. */
    private int[] corners = new int[3 * 1024];
    /** The normal of each corner of a triangle, or −1 for a triangle with no normals; null while none has. */
    private int[] cornerNormals;
    private int count;

    /**
     * Adds the face of the {@code size} corners {@code vertices[0, size)} and their normals (−1 for none), whose
     * coordinates are {@code coordinates}' x, y, z.
     */
    void addFace(int[] vertices, int[] normals, int size, float[] coordinates) {
        boolean fanQuad = size == 4 && EarClipping.isFanQuad(coordinates, 3 * vertices[0], 3 * vertices[1],
                3 * vertices[2], 3 * vertices[3]);
        if (size > 3 && !fanQuad) { // a fan or ears, by the face's one projection
            int[] triangles = earClipping.triangles(vertices, size, coordinates);
            for (int t = 0; t < 3 * (size - 2); t += 3) {
                add(vertices, normals, triangles[t], triangles[t + 1], triangles[t + 2]);
            }
            return;
        }
        for (int k = 1; k + 1 < size; k++) {
            add(vertices, normals, 0, k, k + 1); // a fan around the first corner
        }
    }

    /** The mesh of these triangles on {@code vertices} and {@code normals} (x, y, z each). */
    ObjMesh mesh(float[] vertices, float[] normals) {
        return new ObjMesh(vertices, normals, corners, cornerNormals, count);
    }

    /** Adds the face's corners a, b, c as the next triangle, with their normals if all three have one. */
    private void add(int[] vertices, int[] normals, int a, int b, int c) {
        int at = 3 * count++;
        if (at + 3 > corners.length) {
            corners = Arrays.copyOf(corners, 2 * corners.length);
            cornerNormals = cornerNormals == null ? null : Arrays.copyOf(cornerNormals, corners.length);
        }
        corners[at] = vertices[a];
        corners[at + 1] = vertices[b];
        corners[at + 2] = vertices[c];
        boolean smooth = normals[a] >= 0 && normals[b] >= 0 && normals[c] >= 0;
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
