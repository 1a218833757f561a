package rtd.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.RayTriangle;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.math.Vector3f;

/**
 * The triangles of the OBJ file a {@code mesh} names (Part II, "Geometry"). The arrays are never changed, so the
 * frames of an animation share one mesh.
 *
 * @param vertices      x, y, z of each vertex
 * @param normals       x, y, z of each normal
 * @param corners       three vertex indices per triangle (the array may be longer)
 * @param cornerNormals three normal indices per triangle, or −1 for a triangle with no normals; null if none has
 * @param count         the number of triangles
 */
record ObjMesh(float[] vertices, float[] normals, int[] corners, int[] cornerNormals, int count) {

    /** Triangles per array of numbers: 442 KiB, under half of G1's smallest region, so not "humongous". */
    private static final int BLOCK = 1 << 12;
    /** Larger files do not fit in one Java array. */
    private static final long MAX_FILE_SIZE = Integer.MAX_VALUE - 8;

    /** The triangles, in order, each corner p moved to {@code scale·p + shift}. */
    List<IGeometry> triangles(Vector3f shift, float scale, Color colour, Material material) {
        IGeometry[] triangles = new IGeometry[count];
        Vector3f[] normalVectors = normalVectors();
        float[] numbers = null;
        for (int t = 0; t < count; t++) {
            if (t % BLOCK == 0) {
                numbers = new float[Triangle.NUMBERS * Math.min(BLOCK, count - t)];
            }
            int at = Triangle.NUMBERS * (t % BLOCK);
            triangles[t] = triangle(t, shift, scale, colour, material, numbers, at, normalVectors);
        }
        return Arrays.asList(triangles);
    }

    private Triangle triangle(int t, Vector3f shift, float scale, Color colour, Material material, float[] numbers,
            int at, Vector3f[] normalVectors) {
        RayTriangle.putNumbers(corner(corners[3 * t], shift, scale), corner(corners[3 * t + 1], shift, scale),
                corner(corners[3 * t + 2], shift, scale), numbers, at);
        if (cornerNormals == null || cornerNormals[3 * t] < 0) {
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

    /** The mesh in the OBJ file that group {@code g} names; each mistake in it names the scene's line too. */
    static ObjMesh read(StatementValues values, int g) throws SceneException {
        SourceText scene = values.source;
        String written = values.name(g);
        Path file;
        String shown;
        try {
            Path path = Path.of(written);
            file = scene.folder.resolve(path);
            shown = path.isAbsolute() ? written : shownName(scene.name, path);
        } catch (InvalidPathException e) {
            throw values.errorAtValue(g, 0, "'" + written + "' is not a file path here: " + e.getReason(), null);
        }
        Path key = file.toAbsolutePath().normalize();
        ObjMesh mesh = scene.meshes.get(key); // a scene's text always has its table of meshes; an OBJ file's has none
        if (mesh != null) {
            return mesh;
        }
        byte[] bytes;
        try {
            bytes = readFile(file);
        } catch (IOException e) {
            throw values.errorAtValue(g, 0, "cannot read the mesh file '" + shown + "': " + reason(e),
                    e instanceof NoSuchFileException && written.indexOf('\\') >= 0 ? Hints.forWindowsPath(written)
                            : scene.name.equals(SceneIO.STDIN_NAME)
                                    ? "the scene comes from standard input, so a mesh's path is relative to the "
                                            + "folder rtd runs in; or give the full path"
                                    : "a mesh's path is relative to the folder of the scene file");
        }
        try (SourceText obj = new SourceText(shown, bytes)) {
            mesh = ObjReader.read(obj);
        } catch (SceneException e) {
            String usedBy = "this file is used by " + scene.name + ":" + values.line();
            List<SceneError> errors = e.errors().stream().map(error -> error.saying(error.message(),
                    error.help() == null ? usedBy : error.help() + "; " + usedBy)).toList();
            throw new SceneException(values.placeOfValue(g, 0), errors);
        }
        if (mesh.count() == 0) {
            // else the scene would lose the mesh silently, and the empty picture's warning would blame the camera
            throw values.errorAtValue(g, 0, "the mesh file '" + shown + "' has no faces: rtd found no 'f' line in it",
                    "rtd skips the lines of an OBJ file other than v, vn and f, so a misspelt 'F' or 'face' line is "
                            + "skipped too; a mesh needs at least one face");
        }
        scene.meshes.put(key, mesh);
        return mesh;
    }

    /** The OBJ file's name as the user knows it: the scene's name, with the path in place of its file name. */
    private static String shownName(String sceneName, Path path) {
        try {
            return Path.of(sceneName).resolveSibling(path).toString();
        } catch (InvalidPathException e) {
            return path.toString();
        }
    }

    private static byte[] readFile(Path file) throws IOException {
        String refused = Files.isDirectory(file) ? "it is a folder, not a file"
                : !Files.exists(file) ? null
                : !Files.isRegularFile(file) ? "it is not a regular file" // a device or a pipe: it might never end
                : Files.size(file) > MAX_FILE_SIZE ? "it is larger than 2 GB" : null;
        if (refused != null) {
            throw new FileSystemException(file.toString(), null, refused);
        }
        return SceneIO.readWhole(file); // not Files.readAllBytes: it keeps a buffer as large as the file
    }

    /** Why a file could not be read, in words for a person. */
    private static String reason(IOException e) {
        return e instanceof NoSuchFileException ? "no such file"
                : e instanceof AccessDeniedException ? "permission denied"
                : e instanceof FileSystemException failure && failure.getReason() != null
                        ? failure.getReason().toLowerCase(Locale.ROOT)
                : e.getMessage() != null ? e.getMessage() : "an input error";
    }
}
