package rtd.io;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.Charset;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Map;

/**
 * The bytes of a scene or OBJ file as UTF-8 text, its name and the folder its paths start from, with what a message
 * needs: a line's text, a byte's column in characters, what stands at a place. Of a file that is not UTF-8 it says
 * what it looks like instead: UTF-16, as old Windows editors save; Latin-1 or Windows-1252, as an umlaut in a
 * comment is often saved; or no text at all. Closed once parsed, which lets the bytes go.
 */
final class SourceText implements AutoCloseable {

    /** The most bytes of a token quoted in a message; a longer one is cut, with an ellipsis. */
    private static final int MAX_QUOTED_BYTES = 60;
    private static final Charset WINDOWS_1252 = Charset.forName("windows-1252");
    private static final String SAVE_AS_UTF8 = "save the file as UTF-8";
    /** How many bytes at the start of a file tell whether it is UTF-16. */
    private static final int SAMPLE = 512;

    final String name;
    private byte[] bytes;
    /** The folder a mesh's relative path starts from. */
    final Path folder;
    /** The OBJ files read without a mistake for an animation's other frames, by absolute path; null: none kept. */
    final Map<Path, ObjMesh> meshes;

    SourceText(String name, byte[] bytes, Path folder, Map<Path, ObjMesh> meshes) {
        this.name = name;
        this.bytes = bytes;
        this.folder = folder;
        this.meshes = meshes;
    }

    /** A text whose relative paths start from the current directory, its meshes read anew. */
    SourceText(String name, byte[] bytes) {
        this(name, bytes, Path.of(""), null);
    }

    byte[] bytes() {
        return bytes;
    }

    /** Lets the bytes go: old objects that point to them would keep them through build and render. */
    @Override
    public void close() {
        bytes = null;
    }

    private int lineEnd(int from) {
        int end = from;
        while (end < bytes.length && !TextBytes.isLineBreak(bytes[end])) {
            end++;
        }
        return end;
    }

    /** An error at byte {@code offset} of the line that starts at {@code lineStart}, shown without its line break. */
    SceneError errorAt(int line, int lineStart, int offset, String message, String help) {
        String text = new String(bytes, lineStart, lineEnd(lineStart) - lineStart, StandardCharsets.UTF_8);
        return new SceneError(name, line, column(lineStart, offset), message, text, help);
    }

    int column(int lineStart, int offset) {
        String before = new String(bytes, lineStart, offset - lineStart, StandardCharsets.UTF_8);
        return before.codePointCount(0, before.length()) + 1;
    }

    /** The text of {@code bytes[start, end)} for a message, cut after {@value #MAX_QUOTED_BYTES} bytes. */
    String text(int start, int end) {
        if (end - start <= MAX_QUOTED_BYTES) {
            return new String(bytes, start, end - start, StandardCharsets.UTF_8);
        }
        int cut = start + MAX_QUOTED_BYTES;
        while (cut > start && (bytes[cut] & 0xC0) == 0x80) {
            cut--; // not inside a character of several bytes
        }
        return new String(bytes, start, cut - start, StandardCharsets.UTF_8) + "\u2026";
    }

    String describe(int offset, int lineStart) {
        if (offset >= bytes.length) {
            return offset > lineStart ? "the end of the line" : "the end of the file";
        }
        if (TextBytes.isLineBreak(bytes[offset])) {
            return "the end of the line";
        }
        byte next = offset + 1 < bytes.length ? bytes[offset + 1] : 0;
        if (bytes[offset] == '/' && (next == '/' || next == '*')) {
            return next == '/' ? "a comment" : "'/*'";
        }
        int codePoint = codePointAt(offset);
        if (Character.isISOControl(codePoint)) {
            return String.format("the control character U+%04X", codePoint);
        }
        int after = characterEnd(offset);
        while (TextBytes.isWordByte(bytes[offset]) && after < bytes.length && TextBytes.isWordByte(bytes[after])) {
            after++; // show a whole word, not its first letter
        }
        return Hints.isInvisible(codePoint) ? Hints.nameOf(codePoint) : "'" + text(offset, after) + "'";
    }

    /** The character that starts at {@code offset}, or −1 at the end of the file. */
    int codePointAt(int offset) {
        return offset >= bytes.length ? -1 : text(offset, characterEnd(offset)).codePointAt(0);
    }

    private int characterEnd(int offset) {
        int after = offset + 1;
        while (after < bytes.length && (bytes[after] & 0xC0) == 0x80) {
            after++;
        }
        return after;
    }

    /** The first bad byte of {@code bytes[from, to)}, or −1: the first NUL, unless invalid UTF-8 comes before it. */
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

    /** The error for the bad byte at {@code bad} of a scene whose text starts at {@code start}, after a BOM. */
    SceneError notUtf8(int start, int bad) {
        int line = 1;
        int lineStart = start;
        for (int i = start; i < bad; i++) {
            if (TextBytes.endsLine(bytes, i)) {
                line++;
                lineStart = i + 1;
            }
        }
        int column = column(lineStart, bad);
        String found = bytes[bad] == 0 ? "a NUL byte" : "byte " + hex(bytes[bad]);
        String utf16 = utf16();
        if (utf16 != null) {
            return new SceneError(name, line, column, "the file is not UTF-8 but looks like UTF-16 (" + utf16
                    + "): found " + found, null, SAVE_AS_UTF8);
        }
        if (!looksLikeText()) {
            return new SceneError(name, line, column, "this is not a text file: found " + found
                    + (bytes[bad] == 0 ? "" : ", which is not UTF-8"), null,
                    "a scene is a text file, such as examples/input_rtd.txt");
        }
        String rest = new String(bytes, bad, lineEnd(bad) - bad, WINDOWS_1252); // so that the caret lines up
        return new SceneError(name, line, column, "the file is not UTF-8" + legacy(bytes[bad]),
                new String(bytes, lineStart, bad - lineStart, StandardCharsets.UTF_8) + rest, SAVE_AS_UTF8);
    }

    /** The error for the NUL byte at {@code nul} of an OBJ file, whose lines end at LF. */
    SceneError nulInObj(int nul) {
        int line = 1;
        int lineStart = 0;
        for (int i = 0; i < nul; i++) {
            if (bytes[i] == '\n') {
                line++;
                lineStart = i + 1;
            }
        }
        return new SceneError(name, line, column(lineStart, nul), "this is not a text file: found a NUL byte", null,
                "a mesh is a Wavefront OBJ file, which is text");
    }

    private static String hex(byte b) {
        return String.format("0x%02X", b & 0xFF);
    }

    /** "little-endian, with a byte-order mark" and the like if the file starts as UTF-16 does, else null. */
    private String utf16() {
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
        String order = 2 * oddZeros > pairs && 4 * evenZeros < pairs ? "little"
                : 2 * evenZeros > pairs && 4 * oddZeros < pairs ? "big" : null;
        return order == null ? null : order + "-endian, without a byte-order mark";
    }

    /** Whether the file holds no control character but tab, line breaks and form feed: text, if not UTF-8. */
    private boolean looksLikeText() {
        for (byte b : bytes) {
            if (b >= 0 && b < ' ' && b != '\t' && b != '\n' && b != '\r' && b != '\f' || b == 0x7F) {
                return false;
            }
        }
        return true;
    }

    /** " but looks like Latin-1 …: found byte 0xF6, which is 'ö' there", or only the byte if no encoding has it. */
    private static String legacy(byte b) {
        String inWindows1252 = new String(new byte[] {b}, WINDOWS_1252);
        if (inWindows1252.equals("\uFFFD")) {
            return ": found byte " + hex(b); // one of the few bytes that even Windows-1252 leaves out
        }
        String encodings = (b & 0xFF) >= 0xA0 ? "Latin-1 (ISO-8859-1) or Windows-1252" : "Windows-1252";
        return " but looks like " + encodings + ": found byte " + hex(b) + ", which is '" + inWindows1252 + "' there";
    }
}
