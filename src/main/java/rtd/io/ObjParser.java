package rtd.io;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.IntFunction;
import java.util.stream.IntStream;

/**
 * Reads a Wavefront OBJ file, as a {@code mesh} statement names it, into an {@link ObjMesh}, or
 * throws every mistake found in it (up to one more than {@link SceneParser#MAX_ERRORS}, so that
 * the caller can tell there were more).
 *
 * <p>A large file is cut at line feeds into parts that {@link ObjReader}s read in parallel. A
 * face may name any vertex above it, also one in an earlier part, and counts negative indices
 * back from the last vertex read so far; so one pass over all parts first counts each part's
 * lines, vertices and normals ({@link ObjScan}, in parallel too), and each reader starts its
 * count where the parts before it end. The vertices and normals go straight to their places in
 * the mesh's arrays; the triangles and mistakes of the parts are joined in file order. The mesh
 * and the messages are those of reading the file in one go.
 */
final class ObjParser {

    /**
     * The size of the parts a large file is cut into: a file of less than twice this is one
     * part, read on the calling thread. Measured on 2 busy cores, the 28 MB benchmark mesh
     * (1,002,528 triangles) parsed in 0.87 to 0.93 s as one part and in 1.17 to 1.28 s in parts
     * of 4 MiB (the old reader: 1.10 to 1.22 s): parts read in parallel start cold, and the JIT
     * then costs more than the second core saves.
     */
    private static final int PART_SIZE = 32 << 20;

    private ObjParser() {
    }

    /** The mesh in {@code source}, or every mistake found in it. */
    static ObjMesh parse(SourceText source) throws SceneException {
        return parse(source, PART_SIZE);
    }

    /** As {@link #parse(SourceText)}, cutting the file into parts of about {@code partSize} bytes. */
    static ObjMesh parse(SourceText source, int partSize) throws SceneException {
        byte[] bytes = source.bytes();
        int[] cuts = cuts(bytes, ByteClasses.startsWithByteOrderMark(bytes) ? 3 : 0, partSize);
        int parts = cuts.length - 1;
        ObjScan[] scans = inParallel(parts, k -> ObjScan.of(bytes, cuts[k], cuts[k + 1])).toArray(ObjScan[]::new);
        for (ObjScan scan : scans) {
            if (scan.nul() >= 0) {
                throw new SceneException(List.of(notText(source, scan.nul())), false);
            }
        }
        // What comes before each part: its first line's number, and the vertices and normals above it.
        int[] firstLines = new int[parts + 1];
        int[] firstVertices = new int[parts + 1];
        int[] firstNormals = new int[parts + 1];
        firstLines[0] = 1;
        for (int k = 0; k < parts; k++) {
            firstLines[k + 1] = firstLines[k] + scans[k].lineBreaks();
            firstVertices[k + 1] = firstVertices[k] + scans[k].vertices();
            firstNormals[k + 1] = firstNormals[k] + scans[k].normals();
        }
        float[] vertices = new float[3 * firstVertices[parts]];
        float[] normals = new float[3 * firstNormals[parts]];
        List<ObjPart> read = inParallel(parts, k -> new ObjReader(source, cuts[k], cuts[k + 1], firstLines[k], firstVertices[k],
                firstNormals[k], vertices, normals, expectedTriangles(scans[k])).readAll());
        return join(read, vertices, normals);
    }

    /**
     * About as many triangles as the part's faces make: two per face, as a quad makes, which most
     * models are made of (of triangles, quads or both); a polygon of more corners is rarer, and
     * its part's arrays grow.
     */
    private static int expectedTriangles(ObjScan scan) {
        return 2 * scan.faces();
    }

    /**
     * {@code task} for each part, in order: in parallel if there are several, on the calling
     * thread alone for one, with no stream: starting one would take longer than a small file.
     */
    private static <T> List<T> inParallel(int parts, IntFunction<T> task) {
        return parts == 1 ? List.of(task.apply(0)) : IntStream.range(0, parts).parallel().mapToObj(task).toList();
    }

    /** The parts' triangles one after the other, or their mistakes. */
    private static ObjMesh join(List<ObjPart> parts, float[] vertices, float[] normals) throws SceneException {
        List<SceneError> errors = new ArrayList<>();
        int count = 0;
        for (ObjPart part : parts) {
            errors.addAll(part.errors());
            count += part.count();
        }
        if (!errors.isEmpty()) {
            throw new SceneException(errors.subList(0, Math.min(errors.size(), SceneParser.MAX_ERRORS + 1)), false);
        }
        if (parts.size() == 1) {
            ObjPart only = parts.get(0);
            return new ObjMesh(vertices, normals, only.corners(), only.cornerNormals(), count);
        }
        int[] corners = new int[3 * count];
        int[] cornerNormals = new int[3 * count];
        int at = 0;
        for (ObjPart part : parts) {
            System.arraycopy(part.corners(), 0, corners, at, 3 * part.count());
            System.arraycopy(part.cornerNormals(), 0, cornerNormals, at, 3 * part.count());
            at += 3 * part.count();
        }
        return new ObjMesh(vertices, normals, corners, cornerNormals, count);
    }

    // ---- cutting the file into parts ---------------------------------------------------

    /** Where the parts start, each just after a line feed, and the end of the file last. */
    private static int[] cuts(byte[] bytes, int start, int partSize) {
        int count = Math.max(1, (bytes.length - start) / partSize);
        int[] cuts = new int[count + 1];
        int parts = 0;
        cuts[0] = start;
        for (int k = 1; k < count; k++) {
            int cut = start + (int) ((long) (bytes.length - start) * k / count);
            while (cut < bytes.length && bytes[cut - 1] != '\n') {
                cut++;
            }
            if (cut > cuts[parts] && cut < bytes.length) {
                cuts[++parts] = cut;
            }
        }
        cuts[++parts] = bytes.length;
        return Arrays.copyOf(cuts, parts + 1);
    }

    // ---- a file that is no text ---------------------------------------------------------------

    private static SceneError notText(SourceText source, int nul) {
        byte[] bytes = source.bytes();
        int lineOfNul = 1;
        int startOfLine = 0;
        for (int i = 0; i < nul; i++) {
            if (bytes[i] == '\n') {
                lineOfNul++;
                startOfLine = i + 1;
            }
        }
        return new SceneError(source.name(), lineOfNul, source.column(startOfLine, nul),
                "this is not a text file: found a NUL byte", null, "a mesh is a Wavefront OBJ file, which is text");
    }
}
