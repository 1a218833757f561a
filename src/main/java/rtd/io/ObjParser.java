package rtd.io;

import java.util.List;

/**
 * Reads a Wavefront OBJ file, as a {@code mesh} statement names it, into an {@link ObjMesh}, or
 * throws every mistake found in it (up to one more than {@link SceneParser#MAX_ERRORS}, so that
 * the caller can tell there were more). A file with a NUL byte is no text, and is refused at it
 * before any line is read; the lines themselves are read by {@link ObjReader}.
 */
final class ObjParser {

    private ObjParser() {
    }

    /** The mesh in {@code source}, or every mistake found in it. */
    static ObjMesh parse(SourceText source) throws SceneException {
        byte[] bytes = source.bytes();
        for (int i = 0; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                throw new SceneException(List.of(notText(source, i)), false);
            }
        }
        return new ObjReader(source, ByteClasses.startsWithByteOrderMark(bytes) ? 3 : 0).readAll();
    }

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
