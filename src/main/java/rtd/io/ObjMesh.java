package rtd.io;

import java.util.Arrays;
import java.util.List;
import java.util.stream.IntStream;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Triangle;
import rtd.geometry.TriangleNumbers;
import rtd.image.Color;
import rtd.math.Vector3f;

/**
 * The triangles of an OBJ file as {@link ObjReader} read them, which a {@code mesh} (Part II, "Geometry")
 * places with {@link #triangles}. The arrays are the reader's and are never changed.
 *
 * @param vertices      x, y, z of each vertex
 * @param normals       x, y, z of each normal
 * @param corners       three vertex indices per triangle (the array may be longer)
 * @param cornerNormals three normal indices per triangle, or −1 for a triangle with no normals
 * @param count         the number of triangles
 */
record ObjMesh(float[] vertices, float[] normals, int[] corners, int[] cornerNormals, int count) {

    /** Meshes of fewer triangles are placed on the calling thread: starting tasks would take longer. */
    private static final int PARALLEL_FROM = 1 << 15;
    /**
     * How many triangles share one array of numbers: 442 KiB, under half of G1's smallest region, so that it
     * is not "humongous" (put straight into the old generation).
     */
    private static final int BLOCK = 1 << 12;

    /**
     * The triangles, in order, each corner p moved to {@code scale·p + shift}; one whose corners all name
     * normals is smooth. A large mesh is placed in blocks on all cores, each triangle the same whichever
     * thread makes it.
     */
    List<IGeometry> triangles(Vector3f shift, float scale, Color colour, Material material) {
        IGeometry[] triangles = new IGeometry[count];
        Vector3f[] normalVectors = normalVectors();
        int blocks = (count + BLOCK - 1) / BLOCK;
        if (count < PARALLEL_FROM) {
            for (int b = 0; b < blocks; b++) { // a plain loop: a small mesh is placed before a stream would start
                placeBlock(b, triangles, shift, scale, colour, material, normalVectors);
            }
        } else {
            IntStream.range(0, blocks).parallel().forEach(b -> placeBlock(b, triangles, shift, scale, colour, material,
                    normalVectors));
        }
        return Arrays.asList(triangles);
    }

    /** Makes the triangles of block {@code b} into {@code triangles}, their numbers in one new array. */
    private void placeBlock(int b, IGeometry[] triangles, Vector3f shift, float scale, Color colour, Material material,
            Vector3f[] normalVectors) {
        int first = b * BLOCK;
        int end = Math.min(count, first + BLOCK);
        float[] numbers = new float[Triangle.NUMBERS * (end - first)];
        for (int t = first; t < end; t++) {
            triangles[t] = triangle(t, shift, scale, colour, material, numbers, Triangle.NUMBERS * (t - first), normalVectors);
        }
    }

    /** Triangle {@code t}, its numbers written into {@code numbers} from {@code at}. */
    private Triangle triangle(int t, Vector3f shift, float scale, Color colour, Material material, float[] numbers, int at,
            Vector3f[] normalVectors) {
        TriangleNumbers.putNumbers(corner(corners[3 * t], shift, scale), corner(corners[3 * t + 1], shift, scale),
                corner(corners[3 * t + 2], shift, scale), numbers, at);
        if (cornerNormals[3 * t] < 0) {
            return new Triangle(numbers, at, null, colour, material);
        }
        Vector3f[] normalsOfCorners = {normalVectors[cornerNormals[3 * t]], normalVectors[cornerNormals[3 * t + 1]],
            normalVectors[cornerNormals[3 * t + 2]]};
        return new Triangle(numbers, at, normalsOfCorners, colour, material);
    }

    private Vector3f corner(int vertex, Vector3f shift, float scale) {
        return new Vector3f(scale * vertices[3 * vertex] + shift.x(), scale * vertices[3 * vertex + 1] + shift.y(),
                scale * vertices[3 * vertex + 2] + shift.z());
    }

    /** Each normal as a vector, made once and shared by the corners that name it. */
    private Vector3f[] normalVectors() {
        Vector3f[] vectors = new Vector3f[normals.length / 3];
        for (int i = 0; i < vectors.length; i++) {
            vectors[i] = new Vector3f(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
        }
        return vectors;
    }
}
