package rtd.io;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Reads the Wavefront OBJ that a {@code mesh} uses (Part II, "Geometry"): {@code v x y z [w]}, {@code vn x y z}
 * and {@code f} with corners {@code i}, {@code i/t}, {@code i//n} or {@code i/t/n}, indices from 1 or, negative,
 * back from the last read. Other lines, extra numbers and texture indices are skipped; after a mistake, reading
 * goes on with the next line.
 */
final class ObjReader {

    private static final String CORNER_FORMS = "a corner is written 3, 3/1, 3//2 or 3/1/2";

    private final SourceText source;
    /** The source's bytes, until the file is read (see {@link LineCursor#release}). */
    private byte[] bytes;
    private int pos;
    private int line = 1;
    private int lineStart;

    /** The vertices and normals read so far, x, y, z each; the triangles' corners, three per triangle. */
    private float[] vertices = new float[3 * 1024];
    private int vertexCount;
    private float[] normals = new float[0];
    private int normalCount;
    private int[] corners = new int[3 * 1024];
    /** The normal of each corner of a triangle, or −1 for a triangle with no normals; null while none has. */
    private int[] cornerNormals;
    private int triangleCount;

    /** The current face's corners: vertex and normal (−1 for none) indices. */
    private int[] faceVertices = new int[8];
    private int[] faceNormals = new int[8];
    private final EarClipping earClipping = new EarClipping();
    /** The faces of more than three corners, read as fans: each one's first triangle and its number of corners. */
    private int[] polygons = new int[0];
    private int polygonCount;

    private final List<SceneError> errors = new ArrayList<>();

    /** The mesh in {@code source}, or its mistakes (up to one more than {@link SceneException#MAX_ERRORS}). */
    static ObjMesh read(SourceText source) throws SceneException {
        byte[] bytes = source.bytes();
        for (int i = 0; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                throw new SceneException(List.of(source.nulInObj(i)), false);
            }
        }
        return new ObjReader(source, TextBytes.startsWithByteOrderMark(bytes) ? 3 : 0).readAll();
    }

    private ObjReader(SourceText source, int start) {
        this.source = source;
        this.bytes = source.bytes();
        this.pos = start;
        this.lineStart = start;
    }

    private ObjMesh readAll() throws SceneException {
        while (pos < bytes.length && errors.size() <= SceneException.MAX_ERRORS) {
            try {
                readLine();
            } catch (SceneException e) {
                errors.addAll(e.errors());
            }
            skipToNextLine();
        }
        bytes = null;
        if (!errors.isEmpty()) {
            throw new SceneException(errors.subList(0, Math.min(errors.size(), SceneException.MAX_ERRORS + 1)), false);
        }
        cutPolygons();
        return new ObjMesh(Arrays.copyOf(vertices, 3 * vertexCount), Arrays.copyOf(normals, 3 * normalCount), corners,
                cornerNormals, triangleCount);
    }

    private void readLine() throws SceneException {
        skipBlanks();
        int start = pos;
        while (!atTokenEnd()) {
            pos++;
        }
        int length = pos - start;
        if (length == 1 && bytes[start] == 'v') {
            vertices = room(vertices, 3 * ++vertexCount); // even if the line is wrong: the faces below count it
            readCoordinates(vertices, 3 * vertexCount - 3, "v", "vertex"); // anything after z (w, colours) is skipped
        } else if (length == 2 && bytes[start] == 'v' && bytes[start + 1] == 'n') {
            normals = room(normals, 3 * ++normalCount);
            readCoordinates(normals, 3 * normalCount - 3, "vn", "normal");
        } else if (length == 1 && bytes[start] == 'f') {
            readFace(start);
        }
        // any other line is skipped, whatever it holds
    }

    /** {@code numbers}, or a copy twice as long (3072 at least) if it is shorter than {@code size}. */
    private static float[] room(float[] numbers, int size) {
        return size <= numbers.length ? numbers : Arrays.copyOf(numbers, Math.max(3 * 1024, 2 * numbers.length));
    }

    private void readCoordinates(float[] into, int at, String keyword, String what) throws SceneException {
        for (int k = 0; k < 3; k++) {
            skipBlanks();
            int start = pos;
            while (!atTokenEnd()) {
                pos++;
            }
            if (pos == start) {
                throw error(pos, "expected 3 numbers (x y z) after '" + keyword + "', found " + (k == 0 ? "none" : k),
                        "a " + what + " is written " + keyword + " 0.5 -1 2");
            }
            float value;
            try {
                value = FloatParser.parse(bytes, start, pos);
            } catch (NumberFormatException e) {
                String token = source.text(start, pos);
                throw error(start, "expected a number, found '" + token + "'", Hints.forObjNumber(token));
            }
            if (!Float.isFinite(value)) {
                String written = source.text(start, pos);
                boolean overflow = Hints.tooLarge(written);
                throw error(start, "the " + "xyz".charAt(k) + " of the " + what + " must be a finite number, found "
                        + written
                        + (overflow ? ", which is too large for a float" : ""),
                        overflow ? Hints.FLOAT_RANGE : "a " + what + " is written " + keyword + " 0.5 -1 2");
            }
            into[at + k] = value;
        }
    }

    private void readFace(int keywordStart) throws SceneException {
        int count = 0;
        while (true) {
            skipBlanks();
            if (atTokenEnd()) {
                break;
            }
            if (count == faceVertices.length) {
                faceVertices = Arrays.copyOf(faceVertices, 2 * count);
                faceNormals = Arrays.copyOf(faceNormals, 2 * count);
            }
            readCorner(count++);
        }
        if (count < 3) {
            throw error(keywordStart, "a face needs at least 3 corners, found " + count, CORNER_FORMS);
        }
        if (count > 3 && mixesNormals(count)) { // a fan would drop the normals of its triangles that lack one
            int[] triangles = earClipping.triangles(faceVertices, count, vertices);
            for (int t = 0; t < 3 * (count - 2); t += 3) {
                addTriangle(triangles[t], triangles[t + 1], triangles[t + 2]);
            }
            return;
        }
        if (count > 3) {
            keepPolygon(count);
        }
        for (int k = 1; k + 1 < count; k++) {
            addTriangle(0, k, k + 1); // a fan around the first corner, which cutPolygons cuts again if it must
        }
    }

    /** Whether some corners of the face have a normal and others do not. */
    private boolean mixesNormals(int count) {
        boolean some = false;
        boolean all = true;
        for (int k = 0; k < count; k++) {
            some |= faceNormals[k] >= 0;
            all &= faceNormals[k] >= 0;
        }
        return some && !all;
    }

    /** Notes that a face of {@code count} corners starts at the next triangle, as a fan. */
    private void keepPolygon(int count) {
        if (2 * polygonCount + 2 > polygons.length) {
            polygons = Arrays.copyOf(polygons, Math.max(1024, 2 * polygons.length));
        }
        polygons[2 * polygonCount] = triangleCount;
        polygons[2 * polygonCount + 1] = count;
        polygonCount++;
    }

    /**
     * Cuts each face of more than three corners that is no fan ({@link EarClipping}) into its ears, in the places its
     * fan took. It runs once the whole file is read, in a loop of its own, so that the loop over the lines, which the
     * JIT compiles while a large file is read, stays small.
     */
    private void cutPolygons() {
        for (int p = 0; p < polygonCount; p++) {
            int first = polygons[2 * p];
            int count = polygons[2 * p + 1];
            for (int k = 0; k < count; k++) { // the fan's triangle j is (0, j + 1, j + 2)
                int at = k == 0 ? 3 * first : k < count - 1 ? 3 * (first + k - 1) + 1 : 3 * (first + count - 3) + 2;
                faceVertices[k] = corners[at];
                faceNormals[k] = cornerNormals == null ? -1 : cornerNormals[at];
            }
            if (!earClipping.isFan(faceVertices, count, vertices)) {
                int[] triangles = earClipping.triangles(faceVertices, count, vertices);
                for (int t = 0; t < count - 2; t++) {
                    putTriangle(first + t, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]);
                }
            }
        }
    }

    /** One corner {@code i}, {@code i/t}, {@code i//n} or {@code i/t/n}, kept as corner {@code k}. */
    private void readCorner(int k) throws SceneException {
        int start = pos;
        long vertex = readIndex(start);
        long normal = 0;
        int normalStart = -1;
        if (at('/')) {
            pos++;
            while (!atTokenEnd() && bytes[pos] != '/') {
                pos++; // a texture index, which a flat or smooth triangle does not use
            }
            if (at('/')) {
                pos++;
                normalStart = pos;
                normal = readIndex(start);
            }
        }
        if (!atTokenEnd()) {
            throw cornerError(start);
        }
        faceVertices[k] = resolve(vertex, vertexCount, start, "vertex", "v");
        faceNormals[k] = normalStart < 0 ? -1 : resolve(normal, normalCount, normalStart, "normal", "vn");
    }

    /** A whole number at {@link #pos}, with an optional sign. */
    private long readIndex(int cornerStart) throws SceneException {
        boolean negative = at('-');
        if (negative || at('+')) {
            pos++;
        }
        int digitsStart = pos;
        long value = 0;
        while (pos < bytes.length && bytes[pos] >= '0' && bytes[pos] <= '9') {
            value = Math.min(value * 10 + (bytes[pos] - '0'), Integer.MAX_VALUE + 1L); // beyond any file
            pos++;
        }
        if (pos == digitsStart) {
            throw cornerError(cornerStart);
        }
        return negative ? -value : value;
    }

    /** The index from 0 that {@code index} names among the {@code count} read so far. */
    private int resolve(long index, int count, int at, String what, String keyword) throws SceneException {
        if (index == 0) {
            throw error(at, "a " + what + " index is never 0: they count from 1",
                    "1 is the first '" + keyword + "' line of the file, -1 the last one above the face");
        }
        long resolved = index > 0 ? index - 1 : count + index;
        if (resolved < 0 || resolved >= count) {
            throw error(at, "the " + what + " index " + index + " is out of range: " + count + " "
                    + (count == 1 ? what + " comes" : (what.equals("vertex") ? "vertices" : what + "s") + " come")
                    + " before this face",
                    "1 is the first '" + keyword + "' line of the file, -1 the last one above the face");
        }
        return (int) resolved;
    }

    private void addTriangle(int a, int b, int c) {
        if (3 * triangleCount + 3 > corners.length) {
            corners = Arrays.copyOf(corners, 2 * corners.length);
            cornerNormals = cornerNormals == null ? null : Arrays.copyOf(cornerNormals, corners.length);
        }
        putTriangle(triangleCount++, a, b, c);
    }

    /** Writes the face's corners a, b, c as triangle {@code index}, with their normals if all three have one. */
    private void putTriangle(int index, int a, int b, int c) {
        boolean smooth = faceNormals[a] >= 0 && faceNormals[b] >= 0 && faceNormals[c] >= 0;
        int at = 3 * index;
        corners[at] = faceVertices[a];
        corners[at + 1] = faceVertices[b];
        corners[at + 2] = faceVertices[c];
        if (smooth && cornerNormals == null) { // the first smooth triangle: those before have no normals
            cornerNormals = new int[corners.length];
            Arrays.fill(cornerNormals, -1);
        }
        if (cornerNormals != null) {
            cornerNormals[at] = smooth ? faceNormals[a] : -1;
            cornerNormals[at + 1] = smooth ? faceNormals[b] : -1;
            cornerNormals[at + 2] = smooth ? faceNormals[c] : -1;
        }
    }

    private SceneException cornerError(int start) {
        int after = start;
        while (!TextBytes.endsObjWord(bytes, after)) {
            after++;
        }
        return error(start, "expected a corner of the face, found "
                + (after > start ? "'" + source.text(start, after) + "'"
                : source.describe(start, lineStart)), CORNER_FORMS);
    }

    /** Whether {@link #pos} is at a blank, a comment, the end of the line or of the file. */
    private boolean atTokenEnd() {
        return TextBytes.endsObjWord(bytes, pos);
    }

    private boolean at(char c) {
        return pos < bytes.length && bytes[pos] == c;
    }

    private void skipBlanks() {
        while (pos < bytes.length && TextBytes.isBlank(bytes[pos])) {
            pos++;
        }
    }

    private void skipToNextLine() {
        while (pos < bytes.length && bytes[pos] != '\n') {
            pos++;
        }
        if (pos < bytes.length) {
            pos++;
            line++;
            lineStart = pos;
        }
    }

    private SceneException error(int offset, String message, String help) {
        return new SceneException(source.errorAt(line, lineStart, offset, message, help));
    }
}
