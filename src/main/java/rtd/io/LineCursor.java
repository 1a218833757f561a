package rtd.io;

/**
 * Where the readers of a scene file stand, shared so that the statement, group and expression readers see one
 * position: the byte, its line and the line's start; the moves over the bytes, and an error at a place.
 */
final class LineCursor {

    final SourceText source;
    /** The source's bytes, until {@link #release}. */
    byte[] bytes;
    int pos;
    /** The number of the line being read, from 1, and the offset of its first byte. */
    int line;
    int lineStart;

    /** A cursor at byte {@code start}, the start of line {@code line}. */
    LineCursor(SourceText source, int start, int line) {
        this.source = source;
        this.bytes = source.bytes();
        this.pos = start;
        this.lineStart = start;
        this.line = line;
    }

    /** Lets the bytes go once the file is read, as {@link SourceText#close} does. */
    void release() {
        bytes = null;
    }

    boolean at(char c) {
        return pos < bytes.length && bytes[pos] == c;
    }

    /** Whether the cursor is at ':', blanks and '(': the start of a group. */
    boolean atNextGroup() {
        int after = afterSpaces(pos + 1);
        return bytes[pos] == ':' && after < bytes.length && bytes[after] == '(';
    }

    /** Whether the cursor is at the end of the file or line, or at a {@code //} comment. */
    boolean atEndOfStatement() {
        return pos >= bytes.length || TextBytes.isLineBreak(bytes[pos])
                || pos + 1 < bytes.length && bytes[pos] == '/' && bytes[pos + 1] == '/';
    }

    /** Skips spaces and tabs, not a carriage return: it ends a line ({@link #skipToNextLine}). */
    void skipBlanks() {
        pos = afterSpaces(pos);
    }

    int afterSpaces(int from) {
        int p = from;
        while (p < bytes.length && TextBytes.isSpace(bytes[p])) {
            p++;
        }
        return p;
    }

    /** The offset after the word (letters, digits, '_') from {@code from}; {@code from} if none. */
    int afterWord(int from) {
        int p = from;
        while (p < bytes.length && TextBytes.isWordByte(bytes[p])) {
            p++;
        }
        return p;
    }

    /** Goes past the next line break: LF, CR LF, or a CR alone, as old Mac files end lines. */
    void skipToNextLine() {
        while (pos < bytes.length && !TextBytes.endsLine(bytes, pos)) {
            pos++;
        }
        if (pos < bytes.length) {
            pos++;
            line++;
            lineStart = pos;
        }
    }

    /** What stands at {@code offset}, for "found …" in a message. */
    String describe(int offset) {
        return source.describe(offset, lineStart);
    }

    /** An error at {@code offset}; at an invisible character, the help says what it is and what to do. */
    StatementError error(int offset, String message, String help) {
        int codePoint = offset < bytes.length && bytes[offset] < 0 ? source.codePointAt(offset) : -1;
        return new StatementError(source.errorAt(line, lineStart, offset, message,
                Hints.isInvisible(codePoint) ? Hints.forInvisible(codePoint) : help));
    }
}
