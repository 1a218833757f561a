package rtd.io;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Map;

/**
 * The bytes of a scene (or OBJ) file, its name and the folder its relative paths start from, with what a
 * message needs: a line's text, the column of a byte in characters, what stands at a place. Closed once
 * parsed, which lets the bytes go.
 */
final class SourceText implements AutoCloseable {

    /** The most bytes of a token quoted in a message; a longer one is cut, with an ellipsis. */
    static final int MAX_QUOTED_BYTES = 60;

    private final String name;
    private byte[] bytes;
    private final Path folder;
    /**
     * The OBJ files read for the other frames of one animation (Part III, "Frames on the command line"), by
     * absolute path, or null: each is read anew. A mesh file is the same at every clock, and only files read
     * without a mistake are kept.
     */
    private final Map<Path, ObjMesh> meshes;

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

    String name() {
        return name;
    }

    byte[] bytes() {
        return bytes;
    }

    Path folder() {
        return folder;
    }

    Map<Path, ObjMesh> meshes() {
        return meshes;
    }

    /**
     * Lets the bytes go: a parse lasts long enough to move this text to the old generation, where it would
     * keep the whole file alive through the build and the render.
     */
    @Override
    public void close() {
        bytes = null;
    }

    /** The text of the line that starts at byte {@code lineStart}, without its line break (LF, CR LF or CR). */
    String lineText(int lineStart) {
        int end = lineStart;
        while (end < bytes.length && !TextBytes.isLineBreak(bytes[end])) {
            end++;
        }
        return new String(bytes, lineStart, end - lineStart, StandardCharsets.UTF_8);
    }

    /** An error at byte {@code offset} of line {@code line}, which starts at byte {@code lineStart}. */
    SceneError errorAt(int line, int lineStart, int offset, String message, String help) {
        return new SceneError(name, line, column(lineStart, offset), message, lineText(lineStart), help);
    }

    /** The column, from 1, of byte {@code offset} on the line that starts at {@code lineStart}. */
    int column(int lineStart, int offset) {
        String before = new String(bytes, lineStart, offset - lineStart, StandardCharsets.UTF_8);
        return before.codePointCount(0, before.length()) + 1;
    }

    /**
     * The text of {@code bytes[start, end)}, for a message: a token of 50 MB is quoted by its first
     * {@value #MAX_QUOTED_BYTES} bytes and an ellipsis (cut between characters), not whole.
     */
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

    /** Where the character that starts at {@code offset} ends: after its continuation bytes. */
    private int characterEnd(int offset) {
        int after = offset + 1;
        while (after < bytes.length && (bytes[after] & 0xC0) == 0x80) {
            after++;
        }
        return after;
    }
}
