package rtd.io;

/**
 * Which bytes of a scene or OBJ file are blanks, letters of a keyword, end a number, or end a line;
 * and whether a file starts with UTF-8's byte order mark.
 */
final class ByteClasses {

    private ByteClasses() {
    }

    /** A blank, a carriage return among them: what an OBJ line and a number token end at. */
    static boolean isBlank(byte b) {
        return b == ' ' || b == '\t' || b == '\r' || b == '\f' || b == 0x0B;
    }

    /**
     * A blank within a line of a scene file: not a carriage return, which ends a line there,
     * alone (old Mac files) or before a line feed (Windows files).
     */
    static boolean isSpace(byte b) {
        return b == ' ' || b == '\t' || b == '\f' || b == 0x0B;
    }

    /**
     * Whether the bytes begin with UTF-8's byte order mark (EF BB BF), which some Windows editors
     * write: the scene and OBJ readers start after it.
     */
    static boolean startsWithByteOrderMark(byte[] bytes) {
        return bytes.length >= 3 && (bytes[0] & 0xFF) == 0xEF && (bytes[1] & 0xFF) == 0xBB && (bytes[2] & 0xFF) == 0xBF;
    }

    static boolean isLineBreak(byte b) {
        return b == '\n' || b == '\r';
    }

    static boolean isWordByte(byte b) {
        return (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || b == '_';
    }

    /** Whether {@code b} ends a number: a table, as it is asked for every byte of every number of the file. */
    static boolean isDelimiter(byte b) {
        return DELIMITERS[b & 0xFF];
    }

    /**
     * {@link #isDelimiter} for each byte value: one look-up instead of ten comparisons for each
     * digit of the seven million numbers of a million spheres.
     */
    private static final boolean[] DELIMITERS = new boolean[256];

    static {
        for (int value = 0; value < 256; value++) {
            byte b = (byte) value;
            DELIMITERS[value] = b == '|' || b == ')' || b == '(' || b == ':' || b == '\n' || isBlank(b);
        }
    }

    /**
     * Whether an OBJ file's word (a keyword, a number, a face's corner) ends at {@code bytes[i]}:
     * at a blank, a {@code #} (a comment), the end of the line or of the file.
     */
    static boolean endsObjWord(byte[] bytes, int i) {
        return i >= bytes.length || OBJ_WORD_ENDS[bytes[i] & 0xFF];
    }

    /** {@link #endsObjWord} for each byte value: one look-up for each byte of every number of an OBJ file. */
    private static final boolean[] OBJ_WORD_ENDS = new boolean[256];

    static {
        for (int value = 0; value < 256; value++) {
            byte b = (byte) value;
            OBJ_WORD_ENDS[value] = b == '\n' || b == '#' || isBlank(b);
        }
    }

    /**
     * Whether a line ends just after {@code bytes[i]}: a line feed, or a carriage return not
     * followed by a line feed (a CR LF pair is one line break, which ends after its LF).
     */
    static boolean endsLine(byte[] bytes, int i) {
        return bytes[i] == '\n' || bytes[i] == '\r' && (i + 1 == bytes.length || bytes[i + 1] != '\n');
    }
}
