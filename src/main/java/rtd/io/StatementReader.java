package rtd.io;

import java.util.List;
import java.util.stream.IntStream;
import rtd.geometry.Material;

/**
 * Reads each line of a scene file, {@code keyword:(group):(group)…}, into the {@link SceneContents}; its
 * {@link GroupReader} reads the groups. Each mistake becomes an error at its place and reading goes on with the
 * next line. An object that names a material defined further down waits until the whole file is read.
 */
final class StatementReader {

    private final LineCursor cursor;
    private final GroupReader groupReader;
    private final StatementValues values;
    private final SceneContents contents;
    private int statementStart;
    private Statement current;
    /** Whether the line is inside a {@code /* *}{@code /} comment, which is reported once, at its start. */
    private boolean inBlockComment;

    /** A reader of {@code source} from byte {@code start} (after a byte-order mark), the start of line {@code line}. */
    StatementReader(SourceText source, int start, int line, SceneContents contents, Names names) {
        this.cursor = new LineCursor(source, start, line);
        this.values = new StatementValues(source, names);
        this.groupReader = new GroupReader(cursor, values, names);
        this.contents = contents;
        contents.values = values;
    }

    /** Reads each line that starts before byte {@code end}; stops past {@link SceneException#MAX_ERRORS} errors. */
    void readUntil(int end) {
        while (cursor.pos < end && contents.errors.size() <= SceneException.MAX_ERRORS) {
            try {
                readStatement();
            } catch (SceneException e) {
                contents.addErrors(e);
                keepNameOfBrokenDefinition();
            }
            cursor.skipToNextLine();
        }
    }

    /** Lets the file's bytes go: the reader is done. */
    void release() {
        cursor.release();
    }

    /** Goes on reading at byte {@code start}, the start of line {@code line}, as if it had read the lines above. */
    void moveTo(int start, int line) {
        cursor.pos = start;
        cursor.lineStart = start;
        cursor.line = line;
    }

    private void readStatement() throws SceneException {
        current = null;
        cursor.skipBlanks();
        if (inBlockComment && !leaveBlockComment()) {
            return; // a line inside a /* */ comment, which is reported at its start
        }
        if (cursor.atEndOfStatement()) {
            return; // a blank line or a comment
        }
        Statement statement = readKeyword(false);
        if (statement == null) {
            return; // a line number and nothing else
        }
        contents.statementCount++;
        current = statement;
        values.begin(statement, cursor.line, cursor.lineStart, statementStart);
        int own = statement.groups().size();
        for (int g = 0; g < own; g++) { // no Iterator for each line of a large file
            groupReader.readGroup(statement, statement.group(g));
        }
        cursor.skipBlanks();
        int optional = 0;
        int most = statement.repeatsLast() ? Integer.MAX_VALUE : statement.optional().size();
        while (optional < most && cursor.at(':')) {
            groupReader.readGroup(statement, statement.group(own + optional++));
            cursor.skipBlanks();
        }
        if (cursor.at(':')) {
            throw cursor.error(cursor.pos, "too many groups: '" + statement.keyword() + "' takes "
                    + statement.groupCount(), "write it as " + statement.usage());
        }
        if (!cursor.atEndOfStatement()) {
            throw textAfterStatement();
        }
        if (statement.takesMaterial() && (optional > 0 || values.patternGroup >= 0)) {
            Material above = optional == 1 && values.patternGroup < 0 ? contents.materials.get(values.name(own)) : null;
            if (above == null) {
                contents.addPending(values); // its names are resolved when the whole file is read
                return;
            }
            contents.namedAtOnce.add(values.name(own));
            values.names = new DefinedNames.ObjectNames(above, null, null, List.of());
        }
        values.build(contents);
    }

    /** After a mistake in a definition whose name was read, keeps the name: its users are not told it is unknown. */
    private void keepNameOfBrokenDefinition() {
        if (current != null && current.keyword().equals(Grammar.LET)) {
            Names.brokenLet(values);
        } else if (current != null && !current.takesMaterial() && current.groups().get(0).rule() == Group.Rule.NAME
                && values.hasValue(0)) {
            contents.brokenDefinitions.add(values.name(0));
        }
    }

    /** The keyword's statement, or null for a line of only a line number (as in the paper; noted, then skipped). */
    private Statement readKeyword(boolean afterLineNumber) throws SceneException {
        statementStart = cursor.pos;
        cursor.pos = cursor.afterWord(statementStart);
        if (cursor.pos == statementStart) {
            throw noStatement();
        }
        Statement statement = Grammar.find(cursor.bytes, statementStart, cursor.pos);
        if (statement != null) {
            return statement;
        }
        String word = cursor.source.text(statementStart, cursor.pos);
        if (afterLineNumber || !atLineNumber()) {
            throw cursor.error(statementStart, "unknown statement '" + word + "'", Hints.keywordHelp(word));
        }
        contents.noteLineNumber(cursor.error(statementStart, "the line starts with a line number, '" + word + "'",
                Hints.LINE_NUMBERS).place);
        cursor.skipBlanks();
        return cursor.atEndOfStatement() ? null : readKeyword(true);
    }

    /** Whether the word from {@link #statementStart} to the cursor is digits, then a blank or the end. */
    private boolean atLineNumber() {
        boolean digits = IntStream.range(statementStart, cursor.pos).allMatch(i -> Character.isDigit(cursor.bytes[i]));
        return digits && (cursor.atEndOfStatement() || TextBytes.isSpace(cursor.bytes[cursor.pos]));
    }

    /** A line that starts with neither a keyword nor a comment: perhaps one as other languages write it. */
    private SceneException noStatement() {
        String help = commentHelp();
        if (help == null && cursor.at('/')) {
            help = Hints.COMMENTS + ", two slashes"; // one slash alone: the second was forgotten
        }
        return cursor.error(cursor.pos, "expected a statement (" + Grammar.keywordList() + "), found "
                + cursor.describe(cursor.pos), help);
    }

    /** Text after a whole statement: a comment as other languages write it, a ';', a second statement. */
    private SceneException textAfterStatement() {
        String help = commentHelp();
        if (help == null) {
            boolean semicolon = cursor.at(';');
            String second = secondStatement(semicolon ? cursor.pos + 1 : cursor.pos);
            help = second != null ? second : semicolon ? Hints.SEMICOLON : "a comment after a statement starts with //";
        }
        return cursor.error(cursor.pos, "expected the end of the line after the statement, found "
                + cursor.describe(cursor.pos), help);
    }

    /** The help for a second statement (a keyword, then ':') from {@code from} on, after blanks; or null. */
    private String secondStatement(int from) {
        int start = cursor.afterSpaces(from);
        int end = cursor.afterWord(start);
        Statement statement = Grammar.find(cursor.bytes, start, end);
        int after = cursor.afterSpaces(end);
        return statement != null && after < cursor.bytes.length && cursor.bytes[after] == ':'
                ? "one statement per line: start a new line before '" + statement.keyword() + "'" : null;
    }

    /** The help at a comment as other languages write it ({@code #}, {@code /*}), or null; a {@code /*} is skipped. */
    private String commentHelp() {
        boolean block = cursor.pos + 1 < cursor.bytes.length && cursor.bytes[cursor.pos] == '/'
                && cursor.bytes[cursor.pos + 1] == '*';
        if (!block && !cursor.at('#')) {
            return null;
        }
        inBlockComment = block && commentEnd(cursor.pos + 2) < 0;
        return Hints.COMMENTS;
    }

    /** On a line inside a block comment: whether the comment ends on it; the cursor is then after the end. */
    private boolean leaveBlockComment() {
        int after = commentEnd(cursor.pos);
        inBlockComment = after < 0;
        cursor.pos = inBlockComment ? cursor.pos : cursor.afterSpaces(after);
        return !inBlockComment;
    }

    /** The offset after the first {@code *}{@code /} from {@code from} to the end of its line, or −1. */
    private int commentEnd(int from) {
        for (int i = from; i + 1 < cursor.bytes.length && !TextBytes.isLineBreak(cursor.bytes[i]); i++) {
            if (cursor.bytes[i] == '*' && cursor.bytes[i + 1] == '/') {
                return i + 2;
            }
        }
        return -1;
    }
}
