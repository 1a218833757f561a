package rtd.io;

/**
 * The classes of bytes a scene or OBJ file is read by: blanks, line breaks, the ends of numbers and words,
 * UTF-8's byte-order mark. The ends of numbers are a table: one look-up instead of ten comparisons for each
 * digit of the seven million numbers of a million spheres.
 */
final class TextBytes {

    private static final boolean[] DELIMITERS = endsOf("|)(:\n");
    private static final boolean[] OBJ_WORD_ENDS = endsOf("#\n");

    private TextBytes() {
    }

    /** A blank, a carriage return among them: what an OBJ line and a number token end at. */
    static boolean isBlank(byte b) {
        return b == ' ' || b == '\t' || b == '\r' || b == '\f' || b == 0x0B;
    }

    /** A blank within a line of a scene file: not a carriage return, which ends a line there (alone or before LF). */
    static boolean isSpace(byte b) {
        return b == ' ' || b == '\t' || b == '\f' || b == 0x0B;
    }

    /** Whether the bytes begin with UTF-8's byte order mark, EF BB BF, which some Windows editors write. */
    static boolean startsWithByteOrderMark(byte[] bytes) {
        return bytes.length >= 3 && (bytes[0] & 0xFF) == 0xEF && (bytes[1] & 0xFF) == 0xBB && (bytes[2] & 0xFF) == 0xBF;
    }

    static boolean isLineBreak(byte b) {
        return b == '\n' || b == '\r';
    }

    static boolean isWordByte(byte b) {
        return (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || b == '_';
    }

    /** Whether {@code b} ends a number of a scene file: a blank, a line feed, or one of {@code |)(:}. */
    static boolean isDelimiter(byte b) {
        return DELIMITERS[b & 0xFF];
    }

    /** Whether an OBJ file's word (a keyword, a number, a corner) ends at {@code bytes[i]}: a blank, #, LF, the end. */
    static boolean endsObjWord(byte[] bytes, int i) {
        return i >= bytes.length || OBJ_WORD_ENDS[bytes[i] & 0xFF];
    }

    /** Whether a line ends just after {@code bytes[i]}: a LF, or a CR not before a LF (CR LF ends after its LF). */
    static boolean endsLine(byte[] bytes, int i) {
        return bytes[i] == '\n' || bytes[i] == '\r' && (i + 1 == bytes.length || bytes[i + 1] != '\n');
    }

    private static boolean[] endsOf(String ends) {
        boolean[] table = new boolean[256];
        for (int value = 0; value < 256; value++) {
            table[value] = ends.indexOf(value) >= 0 || isBlank((byte) value);
        }
        return table;
    }
}
