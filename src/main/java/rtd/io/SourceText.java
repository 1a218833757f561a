package rtd.io;

import java.nio.charset.StandardCharsets;

/**
 * The bytes of a scene file and its name, with what an error message needs: the line's text
 * and the column of a byte, counted in characters.
 */
record SourceText(String name, byte[] bytes) {

    /** The text of the line that starts at byte {@code lineStart}, without its line break. */
    String lineText(int lineStart) {
        int end = lineStart;
        while (end < bytes.length && bytes[end] != '\n') {
            end++;
        }
        if (end > lineStart && bytes[end - 1] == '\r') {
            end--;
        }
        return new String(bytes, lineStart, end - lineStart, StandardCharsets.UTF_8);
    }

    /** The column, from 1, of byte {@code offset} on the line that starts at {@code lineStart}. */
    int column(int lineStart, int offset) {
        String before = new String(bytes, lineStart, offset - lineStart, StandardCharsets.UTF_8);
        return before.codePointCount(0, before.length()) + 1;
    }
}
