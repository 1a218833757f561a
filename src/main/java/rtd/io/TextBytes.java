package rtd.io;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.Charset;
import java.nio.charset.CharsetDecoder;
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

    private TextBytes() {
    }

    /** The first bad byte of {@code bytes[from, to)}: the first NUL byte, unless an invalid UTF-8 sequence comes before it. */
    static int firstBadByte(byte[] bytes, int from, int to) {
        boolean ascii = true;
        int nul = to;
        for (int i = from; i < to; i++) {
            if (bytes[i] == 0) {
                nul = i;
                break;
            }
            ascii &= bytes[i] > 0;
        }
        if (ascii) {
            return nul < to ? nul : -1;
        }
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, from, nul - from);
        CoderResult result = decoder.decode(in, CharBuffer.allocate(nul - from), true);
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
            if (TextBytes.endsLine(bytes, i)) {
                line++;
                lineStart = i + 1;
            }
        }
        int column = source.column(lineStart, bad);
        String utf16 = utf16(bytes);
        if (utf16 != null) {
            return new SceneError(source.name(), line, column, "the file is not UTF-8 but looks like UTF-16 (" + utf16
                    + "): found " + name(bytes[bad]), null, SAVE_AS_UTF8);
        }
        if (!looksLikeText(bytes)) {
            String what = bytes[bad] == 0 ? "a NUL byte" : name(bytes[bad]) + ", which is not UTF-8";
            return new SceneError(source.name(), line, column, "this is not a text file: found " + what, null,
                    "a scene is a text file, such as examples/input_rtd.txt");
        }
        return new SceneError(source.name(), line, column, "the file is not UTF-8" + legacy(bytes[bad]),
                legacyLine(bytes, lineStart, bad), SAVE_AS_UTF8);
    }

    private static String name(byte b) {
        return b == 0 ? "a NUL byte" : String.format("byte 0x%02X", b & 0xFF);
    }

    /**
     * "little-endian, with a byte-order mark" and the like if the file looks like UTF-16: it
     * starts with UTF-16's byte-order mark, or (mostly ASCII text) every other byte of its
     * start is 0; otherwise null.
     */
    private static String utf16(byte[] bytes) {
        if (bytes.length >= 2 && (bytes[0] & 0xFF) == 0xFF && (bytes[1] & 0xFF) == 0xFE) {
            return "little-endian, with a byte-order mark";
        }
        if (bytes.length >= 2 && (bytes[0] & 0xFF) == 0xFE && (bytes[1] & 0xFF) == 0xFF) {
            return "big-endian, with a byte-order mark";
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
        if (pairs > 0 && 2 * evenZeros > pairs && 4 * oddZeros < pairs) {
            return "big-endian, without a byte-order mark";
        }
        return null;
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
        String hex = String.format("0x%02X", b & 0xFF);
        if (inWindows1252.equals("\uFFFD")) {
            return ": found byte " + hex; // one of the few bytes that even Windows-1252 leaves out
        }
        String encodings = (b & 0xFF) >= 0xA0 ? "Latin-1 (ISO-8859-1) or Windows-1252" : "Windows-1252";
        return " but looks like " + encodings + ": found byte " + hex + ", which is '" + inWindows1252 + "' there";
    }

    /** The line, its UTF-8 start as UTF-8 and its rest from the bad byte on as Windows-1252, so that the caret lines up. */
    private static String legacyLine(byte[] bytes, int lineStart, int bad) {
        int end = bad;
        while (end < bytes.length && !TextBytes.isLineBreak(bytes[end])) {
            end++;
        }
        return new String(bytes, lineStart, bad - lineStart, StandardCharsets.UTF_8)
                + new String(bytes, bad, end - bad, WINDOWS_1252);
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

    // ---- classes of bytes ----------------------------------------------------------------


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
