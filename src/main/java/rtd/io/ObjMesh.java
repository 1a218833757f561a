package rtd.io;

import java.util.ArrayList;
import java.util.List;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.math.Vector3f;

/**
 * The triangles of a Wavefront OBJ file as {@link ObjReader} read them: the vertices and normals,
 * and for each triangle, in face order, the index of each corner's vertex and normal. A
 * {@code mesh} statement (Part II of the spec) places them in the scene with
 * {@link #triangles}. The arrays are the reader's own and are never changed.
 *
 * @param vertices      x, y, z of each vertex
 * @param normals       x, y, z of each normal
 * @param corners       three vertex indices per triangle
 * @param cornerNormals three normal indices per triangle, or −1 for a triangle with no normals
 * @param count         the number of triangles
 */
record ObjMesh(float[] vertices, float[] normals, int[] corners, int[] cornerNormals, int count) {

    /**
     * The triangles, in order, each corner p moved to {@code scale·p + shift}. A triangle whose
     * every corner named a normal is smooth, with those normals as written: a scale above 0
     * does not turn them.
     */
    List<IGeometry> triangles(Vector3f shift, float scale, Color colour, Material material) {
        List<IGeometry> triangles = new ArrayList<>(count);
        for (int t = 0; t < count; t++) {
            Vector3f p1 = corner(corners[3 * t], shift, scale);
            Vector3f p2 = corner(corners[3 * t + 1], shift, scale);
            Vector3f p3 = corner(corners[3 * t + 2], shift, scale);
            if (cornerNormals[3 * t] < 0) {
                triangles.add(new Triangle(p1, p2, p3, colour, material));
            } else {
                Vector3f[] normalsOfCorners = {normal(cornerNormals[3 * t]), normal(cornerNormals[3 * t + 1]),
                    normal(cornerNormals[3 * t + 2])};
                triangles.add(new Triangle(p1, p2, p3, normalsOfCorners, colour, material));
            }
        }
        return triangles;
    }

    private Vector3f corner(int vertex, Vector3f shift, float scale) {
        return new Vector3f(scale * vertices[3 * vertex] + shift.x(), scale * vertices[3 * vertex + 1] + shift.y(),
                scale * vertices[3 * vertex + 2] + shift.z());
    }

    private Vector3f normal(int index) {
        return new Vector3f(normals[3 * index], normals[3 * index + 1], normals[3 * index + 2]);
    }
}
