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

    /** The vertices and normals read so far, x, y, z each, and the triangles of the faces. */
    private float[] vertices = new float[3 * 1024];
    private int vertexCount;
    private float[] normals = new float[0];
    private int normalCount;
    private final FaceTriangles triangles = new FaceTriangles();

    /** The current face's corners: vertex and normal (−1 for none) indices. */
    private int[] faceVertices = new int[8];
    private int[] faceNormals = new int[8];

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
        return triangles.mesh(Arrays.copyOf(vertices, 3 * vertexCount), Arrays.copyOf(normals, 3 * normalCount));
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
                        + written + (overflow ? ", which is too large for a float" : ""),
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
        triangles.addFace(faceVertices, faceNormals, count, vertices);
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
