package rtd.io;

/**
 * Where a reader of a stretch of whole lines of a scene file stands, and the moves over its
 * bytes that every level of the reader shares: look at the byte here, skip blanks, go to the next
 * line, make an error at a place on the line. It is the base of {@link GroupReader}, which reads
 * a statement's groups, and so of {@link StatementReader}, which reads whole statements; the three
 * share one position, as fields of one object, so that reading a line of numbers makes no object
 * and goes through no interface.
 */
abstract sealed class LineCursor permits GroupReader {

    final SourceText source;
    /** The source's bytes, until {@link StatementReader#readAll} is done (see {@link SourceText#close}). */
    byte[] bytes;
    /** The end of the stretch of lines to read. */
    final int end;
    /** The byte being read. */
    int pos;
    /** The number of the line being read, and where it starts. */
    int line;
    int lineStart;

    /**
     * A cursor at {@code source.bytes()[start]}, which begins a line (numbered {@code firstLine});
     * the stretch ends at {@code end}, after a line break or at the end of the file.
     */
    LineCursor(SourceText source, int start, int end, int firstLine) {
        this.source = source;
        this.bytes = source.bytes();
        this.end = end;
        this.pos = start;
        this.lineStart = start;
        this.line = firstLine;
    }

    /** Whether {@link #pos} is at ':', blanks and '(': the start of a group. */
    final boolean atNextGroup() {
        if (bytes[pos] != ':') {
            return false;
        }
        int after = pos + 1;
        while (after < bytes.length && ByteClasses.isSpace(bytes[after])) {
            after++;
        }
        return after < bytes.length && bytes[after] == '(';
    }

    final boolean at(char c) {
        return pos < bytes.length && bytes[pos] == c;
    }

    /** Skips spaces and tabs, not a carriage return: it ends a line ({@link #skipToNextLine}). */
    final void skipBlanks() {
        while (pos < bytes.length && ByteClasses.isSpace(bytes[pos])) {
            pos++;
        }
    }

    final boolean atEndOfStatement() {
        return pos >= bytes.length || ByteClasses.isLineBreak(bytes[pos]) || atComment();
    }

    private boolean atComment() {
        return pos + 1 < bytes.length && bytes[pos] == '/' && bytes[pos + 1] == '/';
    }

    /** Goes past the next line break: LF, CR LF, or a CR alone, as old Mac files end lines. */
    final void skipToNextLine() {
        while (pos < end && !ByteClasses.isLineBreak(bytes[pos])) {
            pos++;
        }
        if (pos < end) {
            if (bytes[pos] == '\r' && pos + 1 < end && bytes[pos + 1] == '\n') {
                pos++;
            }
            pos++;
            line++;
            lineStart = pos;
        }
    }

    /** An error at {@code offset}; at an invisible character, the help says what it is and what to do. */
    final StatementError error(int offset, String message, String help) {
        int codePoint = offset < bytes.length && bytes[offset] < 0 ? source.codePointAt(offset) : -1;
        return new StatementError(new SceneError(source.name(), line, source.column(lineStart, offset), message,
                source.lineText(lineStart), Hints.isInvisible(codePoint) ? Hints.forInvisible(codePoint) : help));
    }
}
