package rtd.io;

import java.util.List;

/**
 * The faces of a part of an OBJ file as {@link ObjReader} read them, split into triangles, and
 * the mistakes found in the part; its vertices and normals went straight into the mesh's arrays.
 *
 * @param corners       three vertex indices (from 0, in the whole file) per triangle
 * @param cornerNormals three normal indices per triangle, or −1 for a triangle with no normals
 * @param count         the number of triangles; the arrays may be longer
 * @param errors        the mistakes, in file order
 */
record ObjPart(int[] corners, int[] cornerNormals, int count, List<SceneError> errors) {
}
