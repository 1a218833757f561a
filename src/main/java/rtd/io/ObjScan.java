package rtd.io;

/**
 * What one pass over a part of an OBJ file tells before the part is read: whether it holds a NUL
 * byte (then the file is no text), how many lines end in it, and how many of its lines are
 * vertices, normals and faces. From these follow, for each part, the number of its first line
 * and of its first vertex and normal: what {@link ObjReader} needs to read the part on its own,
 * in parallel with the others, and resolve a face's negative indices (counted back from the
 * last vertex read so far) as reading the whole file in one go would.
 *
 * <p>A line is a vertex, a normal or a face as {@link ObjReader} decides it: by its first word,
 * after blanks, ending at a blank, a {@code #} or the end of the line. A vertex line with a
 * mistake counts too, as the reader counts it.
 *
 * @param nul        the offset of the first NUL byte, or −1 if none
 * @param lineBreaks the number of line feeds (an OBJ line ends at LF; a CR is a blank)
 * @param vertices   the number of {@code v} lines
 * @param normals    the number of {@code vn} lines
 * @param faces      the number of {@code f} lines
 */
record ObjScan(int nul, int lineBreaks, int vertices, int normals, int faces) {

    private static final int OTHER = 0;
    private static final int VERTEX = 1;
    private static final int NORMAL = 2;
    private static final int FACE = 3;

    /** Scans {@code bytes[from, to)}, which starts a line and ends after a line feed or at the end of the file. */
    static ObjScan of(byte[] bytes, int from, int to) {
        int lineBreaks = 0;
        int[] kinds = new int[4];
        if (from < to) {
            kinds[kindOfLine(bytes, from)]++;
        }
        for (int i = from; i < to; i++) {
            byte b = bytes[i];
            if (b <= '\n') { // one test for the rare bytes: line feeds, NUL (and every non-ASCII byte)
                if (b == '\n') {
                    lineBreaks++;
                    if (i + 1 < to) {
                        kinds[kindOfLine(bytes, i + 1)]++;
                    }
                } else if (b == 0) {
                    return new ObjScan(i, lineBreaks, 0, 0, 0);
                }
            }
        }
        return new ObjScan(-1, lineBreaks, kinds[VERTEX], kinds[NORMAL], kinds[FACE]);
    }

    /** What the line that starts at {@code start} is, by its first word: a vertex, a normal, a face or other. */
    private static int kindOfLine(byte[] bytes, int start) {
        int i = start;
        while (i < bytes.length && ByteClasses.isBlank(bytes[i])) {
            i++;
        }
        if (i < bytes.length && bytes[i] == 'v') {
            if (ByteClasses.endsObjWord(bytes, i + 1)) {
                return VERTEX;
            }
            return bytes[i + 1] == 'n' && ByteClasses.endsObjWord(bytes, i + 2) ? NORMAL : OTHER;
        }
        return i < bytes.length && bytes[i] == 'f' && ByteClasses.endsObjWord(bytes, i + 1) ? FACE : OTHER;
    }
}
