package rtd.io;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.Charset;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * What the bytes of a scene or OBJ file are: blanks, ends of numbers, words and lines, UTF-8's byte
 * order mark; and the first byte that is not UTF-8 text (a NUL byte, bytes that are not UTF-8),
 * with what the file looks like instead: UTF-16, as some old Windows editors save; Latin-1 or
 * Windows-1252, as editors in Germany and elsewhere save an umlaut in a comment; or no text at all,
 * such as a picture. For text in another encoding the help is to save the file as UTF-8. An OBJ file
 * is refused for a NUL byte only ({@link #inObjFile}).
 */
final class TextBytes {

    private static final Charset WINDOWS_1252 = Charset.forName("windows-1252");
    private static final String SAVE_AS_UTF8 = "save the file as UTF-8";
    /** How many bytes at the start of a file tell whether it is UTF-16. */
    private static final int SAMPLE = 512;
    /**
     * Whether a byte ends a number of a scene file, or a word of an OBJ file: one look-up instead of ten
     * comparisons for each digit of the seven million numbers of a million spheres.
     */
    private static final boolean[] DELIMITERS = endsOf("|)(:\n");
    private static final boolean[] OBJ_WORD_ENDS = endsOf("#\n");

    private TextBytes() {
    }

    /** The first bad byte of {@code bytes[from, to)}: the first NUL byte, unless an invalid UTF-8 sequence comes before it. */
    static int firstBadByte(byte[] bytes, int from, int to) {
        boolean ascii = true;
        int nul = to;
        for (int i = from; i < to && nul == to; i++) {
            nul = bytes[i] == 0 ? i : to;
            ascii &= bytes[i] >= 0;
        }
        if (ascii) {
            return nul < to ? nul : -1;
        }
        ByteBuffer in = ByteBuffer.wrap(bytes, from, nul - from);
        CoderResult result = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT).decode(in, CharBuffer.allocate(nul - from), true);
        return result.isError() ? in.position() : nul < to ? nul : -1;
    }

    /**
     * The error for the bad byte at {@code bad}: where it is, and what the file looks like. The
     * text starts at {@code start}, after a UTF-8 byte-order mark if the file has one.
     */
    static SceneError error(SourceText source, int start, int bad) {
        byte[] bytes = source.bytes();
        int line = 1;
        int lineStart = start;
        for (int i = start; i < bad; i++) {
            if (endsLine(bytes, i)) {
                line++;
                lineStart = i + 1;
            }
        }
        int column = source.column(lineStart, bad);
        String utf16 = utf16(bytes);
        if (utf16 != null) {
            return new SceneError(source.name(), line, column, "the file is not UTF-8 but looks like UTF-16 (" + utf16
                    + "): found " + (bytes[bad] == 0 ? "a NUL byte" : "byte " + hex(bytes[bad])), null, SAVE_AS_UTF8);
        }
        if (!looksLikeText(bytes)) {
            String what = bytes[bad] == 0 ? "a NUL byte" : "byte " + hex(bytes[bad]) + ", which is not UTF-8";
            return new SceneError(source.name(), line, column, "this is not a text file: found " + what, null,
                    "a scene is a text file, such as examples/input_rtd.txt");
        }
        return new SceneError(source.name(), line, column, "the file is not UTF-8" + legacy(bytes[bad]),
                legacyLine(bytes, lineStart, bad), SAVE_AS_UTF8);
    }

    /** The error for the NUL byte at {@code nul} of an OBJ file, whose lines end at LF. */
    static SceneError inObjFile(SourceText source, int nul) {
        byte[] bytes = source.bytes();
        int line = 1;
        int lineStart = 0;
        for (int i = 0; i < nul; i++) {
            if (bytes[i] == '\n') {
                line++;
                lineStart = i + 1;
            }
        }
        return new SceneError(source.name(), line, source.column(lineStart, nul), "this is not a text file: found a NUL byte",
                null, "a mesh is a Wavefront OBJ file, which is text");
    }

    private static String hex(byte b) {
        return String.format("0x%02X", b & 0xFF);
    }

    /**
     * "little-endian, with a byte-order mark" and the like if the file looks like UTF-16: it
     * starts with UTF-16's byte-order mark, or (mostly ASCII text) every other byte of its
     * start is 0; otherwise null.
     */
    private static String utf16(byte[] bytes) {
        int first = bytes.length >= 2 ? (bytes[0] & 0xFF) << 8 | bytes[1] & 0xFF : 0;
        if (first == 0xFFFE || first == 0xFEFF) {
            return (first == 0xFFFE ? "little" : "big") + "-endian, with a byte-order mark";
        }
        int pairs = Math.min(bytes.length, SAMPLE) / 2;
        int evenZeros = 0;
        int oddZeros = 0;
        for (int k = 0; k < pairs; k++) {
            evenZeros += bytes[2 * k] == 0 ? 1 : 0;
            oddZeros += bytes[2 * k + 1] == 0 ? 1 : 0;
        }
        if (pairs > 0 && 2 * oddZeros > pairs && 4 * evenZeros < pairs) {
            return "little-endian, without a byte-order mark";
        }
        return pairs > 0 && 2 * evenZeros > pairs && 4 * oddZeros < pairs ? "big-endian, without a byte-order mark"
                : null;
    }

    /** Whether the file holds no NUL and no control character but tab, line breaks and form feed: text, if not UTF-8. */
    private static boolean looksLikeText(byte[] bytes) {
        for (byte b : bytes) {
            if (b >= 0 && b < ' ' && b != '\t' && b != '\n' && b != '\r' && b != '\f' || b == 0x7F) {
                return false;
            }
        }
        return true;
    }

    /** ": it looks like Latin-1 …, where byte 0xF6 is 'ö'", or only the byte if no such encoding has a letter for it. */
    private static String legacy(byte b) {
        String inWindows1252 = new String(new byte[] {b}, WINDOWS_1252);
        if (inWindows1252.equals("\uFFFD")) {
            return ": found byte " + hex(b); // one of the few bytes that even Windows-1252 leaves out
        }
        String encodings = (b & 0xFF) >= 0xA0 ? "Latin-1 (ISO-8859-1) or Windows-1252" : "Windows-1252";
        return " but looks like " + encodings + ": found byte " + hex(b) + ", which is '" + inWindows1252 + "' there";
    }

    /** The line, its UTF-8 start as UTF-8 and its rest from the bad byte on as Windows-1252, so that the caret lines up. */
    private static String legacyLine(byte[] bytes, int lineStart, int bad) {
        int end = bad;
        while (end < bytes.length && !isLineBreak(bytes[end])) {
            end++;
        }
        return new String(bytes, lineStart, bad - lineStart, StandardCharsets.UTF_8)
                + new String(bytes, bad, end - bad, WINDOWS_1252);
    }

    // ---- classes of bytes ----------------------------------------------------------------

    /** A blank, a carriage return among them: what an OBJ line and a number token end at. */
    static boolean isBlank(byte b) {
        return b == ' ' || b == '\t' || b == '\r' || b == '\f' || b == 0x0B;
    }

    /** A blank within a line of a scene file: not a carriage return, which ends a line there (alone or before LF). */
    static boolean isSpace(byte b) {
        return b == ' ' || b == '\t' || b == '\f' || b == 0x0B;
    }

    /** Whether the bytes begin with UTF-8's byte order mark (EF BB BF), which some Windows editors write. */
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

    /**
     * Whether an OBJ file's word (a keyword, a number, a corner) ends at {@code bytes[i]}: a blank, {@code #}, LF, the
     * end.
     */
    static boolean endsObjWord(byte[] bytes, int i) {
        return i >= bytes.length || OBJ_WORD_ENDS[bytes[i] & 0xFF];
    }

    /** A table of each byte value: whether it is a blank or one of {@code ends}. */
    private static boolean[] endsOf(String ends) {
        boolean[] table = new boolean[256];
        for (int value = 0; value < 256; value++) {
            table[value] = ends.indexOf(value) >= 0 || isBlank((byte) value);
        }
        return table;
    }

    /**
     * Whether a line ends just after {@code bytes[i]}: a LF, or a CR not followed by a LF (CR LF ends after its LF).
     */
    static boolean endsLine(byte[] bytes, int i) {
        return bytes[i] == '\n' || bytes[i] == '\r' && (i + 1 == bytes.length || bytes[i + 1] != '\n');
    }
}
