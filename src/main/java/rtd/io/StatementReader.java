package rtd.io;

import java.util.List;
import rtd.geometry.Material;

/**
 * Reads the statements of a stretch of whole lines of a scene file into a {@link ScenePart}:
 * the syntax {@code keyword:(group):(group)…} of the scene file (paper, section 4.1, and Part II,
 * "The scene file"), for any statement of the {@link Grammar}.
 *
 * <p>Each mistake becomes a {@link SceneError} with line and column, and reading goes on with
 * the next line. It works on bytes, not on a String, and makes no object per number. An object
 * that names a material is built at once if the part defines the material above it
 * ({@link ScenePart#materialAbove}); else it waits in the part until the whole file is read (the
 * material may be defined further down). Every other statement is built at once.
 *
 * <p>This class reads a line's keyword and what may follow its groups (comments, mistakes);
 * the groups themselves are read by {@link GroupReader}, which it extends, and the position on
 * the line is its {@link LineCursor}. What a statement makes goes to the part through a
 * {@link PartOutput}.
 */
final class StatementReader extends GroupReader {

    private final ScenePart part;
    private final Statement.Output output;
    /** Where the statement being read starts, for a later message about it. */
    private int statementStart;
    /** The statement being read, once its keyword is known; null before. */
    private Statement current;
    /**
     * Whether the line being read is inside a {@code /* *}{@code /} comment, which is reported once,
     * at its start: the lines up to its end are skipped.
     */
    private boolean inBlockComment;

    /**
     * A reader for {@code source.bytes()[start, end)}, which begins a line (numbered
     * {@code firstLine}) and ends after a line break or at the end of the file.
     */
    StatementReader(SourceText source, int start, int end, int firstLine, ScenePart part) {
        super(source, start, end, firstLine);
        this.part = part;
        this.output = new PartOutput(this, part, values);
    }

    /** Reads every line, until the end or one error past {@link SceneParser#MAX_ERRORS}. */
    void readAll() {
        while (pos < end && part.errors.size() <= SceneParser.MAX_ERRORS) {
            try {
                readStatement();
            } catch (StatementError e) {
                part.addErrors(e);
                keepNameOfBrokenDefinition();
            }
            skipToNextLine();
        }
        part.endsInBlockComment = inBlockComment;
        bytes = null;
    }

    // ---- one statement ------------------------------------------------------------------

    private void readStatement() throws StatementError {
        current = null;
        skipBlanks();
        if (inBlockComment && !leaveBlockComment()) {
            return; // a line inside a /* */ comment, which is reported at its start
        }
        if (atEndOfStatement()) {
            return; // a blank line or a comment
        }
        Statement statement = readKeyword(false);
        if (statement == null) {
            return; // a line number and nothing else
        }
        part.statementCount++;
        current = statement;
        values.begin(statement, line, lineStart);
        List<Group> groups = statement.groups();
        for (int g = 0; g < groups.size(); g++) { // no Iterator for each line of a large file
            readGroup(statement, groups.get(g));
        }
        skipBlanks();
        boolean namesMaterial = statement.takesMaterial() && at(':');
        if (namesMaterial) {
            readGroup(statement, Statement.MATERIAL);
            skipBlanks();
        }
        if (at(':')) {
            throw error(pos, "too many groups: '" + statement.keyword() + "' takes " + statement.groupCount(),
                    "write it as " + statement.usage());
        }
        if (!atEndOfStatement()) {
            throw textAfterStatement();
        }
        if (!namesMaterial) {
            statement.builder().build(values, output);
            return;
        }
        String name = values.name(groups.size());
        Material above = part.materialAbove(name);
        if (above == null) {
            part.addPending(values.copy()); // the material may be defined further down
            return;
        }
        part.namedAtOnce.add(name);
        values.useMaterial(above);
        statement.builder().build(values, output);
    }

    /**
     * After a mistake in a statement that defines a name (its first group is a name, as in
     * {@code material:}), keeps the name if it was read: the objects that use it are then not
     * also told that it is unknown.
     */
    private void keepNameOfBrokenDefinition() {
        if (current != null && !current.takesMaterial() && current.groups().get(0).kind() == Group.Kind.NAME
                && values.hasValue(0)) {
            part.brokenDefinitions.add(values.name(0));
        }
    }

    /**
     * Reads the keyword at {@link #pos}: the statement it names, or null if the line holds only a
     * line number. A line number, as in the paper's listing, is noted in the part (which reports
     * them all as one mistake) and the statement after it is read as if it were not there.
     */
    private Statement readKeyword(boolean afterLineNumber) throws StatementError {
        statementStart = pos;
        while (pos < bytes.length && ByteClasses.isWordByte(bytes[pos])) {
            pos++;
        }
        if (pos == statementStart) {
            throw noStatement();
        }
        Statement statement = Grammar.find(bytes, statementStart, pos);
        if (statement != null) {
            return statement;
        }
        if (afterLineNumber || !atLineNumber()) {
            throw unknownKeyword(statementStart);
        }
        part.noteLineNumber(error(statementStart, "the line starts with a line number, '" + source.text(statementStart, pos)
                + "'", Hints.LINE_NUMBERS).place());
        skipBlanks();
        return atEndOfStatement() ? null : readKeyword(true);
    }

    /** Whether the word from {@link #statementStart} to {@link #pos} is a line number: digits, then a blank or the end. */
    private boolean atLineNumber() {
        for (int i = statementStart; i < pos; i++) {
            if (bytes[i] < '0' || bytes[i] > '9') {
                return false;
            }
        }
        return atEndOfStatement() || ByteClasses.isSpace(bytes[pos]);
    }

    private StatementError unknownKeyword(int keywordStart) {
        String word = source.text(keywordStart, pos);
        return error(keywordStart, "unknown statement '" + word + "'", Suggestions.keywordHelp(word));
    }

    /** A line that starts with neither a keyword nor a comment: perhaps one as other languages write it. */
    private StatementError noStatement() {
        String help = null;
        if (at('#') || atBlockComment()) {
            help = Hints.COMMENTS;
            openBlockComment();
        } else if (at('/')) {
            help = Hints.COMMENTS + ", two slashes"; // one slash alone: the second was forgotten
        }
        return error(pos, "expected a statement (" + Grammar.keywordList() + "), found " + source.describe(pos, lineStart), help);
    }

    /** Text after a whole statement: a comment as other languages write it, a ';', a second statement. */
    private StatementError textAfterStatement() {
        String help;
        if (at('#') || atBlockComment()) {
            help = Hints.COMMENTS;
            openBlockComment();
        } else if (at(';')) {
            String second = secondStatement(pos + 1);
            help = second != null ? second : Hints.SEMICOLON;
        } else {
            String second = secondStatement(pos);
            help = second != null ? second : "a comment after a statement starts with //";
        }
        return error(pos, "expected the end of the line after the statement, found " + source.describe(pos, lineStart), help);
    }

    /** The help for a second statement (a keyword, then ':') from {@code from} on, after blanks; or null. */
    private String secondStatement(int from) {
        int start = from;
        while (start < bytes.length && ByteClasses.isSpace(bytes[start])) {
            start++;
        }
        int end = start;
        while (end < bytes.length && ByteClasses.isWordByte(bytes[end])) {
            end++;
        }
        Statement statement = Grammar.find(bytes, start, end);
        int after = end;
        while (after < bytes.length && ByteClasses.isSpace(bytes[after])) {
            after++;
        }
        return statement != null && after < bytes.length && bytes[after] == ':'
                ? Hints.oneStatementPerLine(statement.keyword()) : null;
    }

    // ---- comments as other languages write them ---------------------------------------------

    private boolean atBlockComment() {
        return pos + 1 < bytes.length && bytes[pos] == '/' && bytes[pos + 1] == '*';
    }

    /** At a {@code /*}: if the comment does not end on this line, skips the lines up to its end. */
    private void openBlockComment() {
        inBlockComment = atBlockComment() && commentEnd(pos + 2) < 0;
    }

    /** On a line inside a block comment: whether the comment ends on it; {@link #pos} is then after the end. */
    private boolean leaveBlockComment() {
        int after = commentEnd(pos);
        if (after < 0) {
            return false;
        }
        inBlockComment = false;
        pos = after;
        skipBlanks();
        return true;
    }

    /** The offset after the first {@code *}{@code /} from {@code from} to the end of its line, or −1. */
    private int commentEnd(int from) {
        for (int i = from; i + 1 < end && !ByteClasses.isLineBreak(bytes[i]); i++) {
            if (bytes[i] == '*' && bytes[i + 1] == '/') {
                return i + 2;
            }
        }
        return -1;
    }

    /** Where the statement being read stands, for a later message about it. */
    SceneError located() {
        return new SceneError(source.name(), line, source.column(lineStart, statementStart), "", source.lineText(lineStart), null);
    }
}
