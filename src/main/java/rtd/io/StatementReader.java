package rtd.io;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.scene.Light;

/**
 * Reads the statements of a stretch of whole lines of a scene file into a {@link ScenePart}:
 * the syntax {@code keyword:(group):(group)…} of the scene file (paper, section 4.1, and Part II
 * of the spec), for any statement of the {@link Grammar}.
 *
 * <p>Each mistake becomes a {@link SceneError} with line and column, and reading goes on with
 * the next line. It works on bytes, not on a String, and makes no object per number. An object
 * that names a material waits in the part until the whole file is read (the material may be
 * defined further down); every other statement is built at once.
 */
final class StatementReader {

    private final SourceText source;
    /** The source's bytes, until {@link #readAll} is done (see {@link SourceText#close}). */
    private byte[] bytes;
    private final int end;
    private final ScenePart part;
    private final GroupValues values;
    private final Statement.Output output = new PartOutput();
    private int pos;
    private int line;
    private int lineStart;
    /** Where the statement being read starts, for a later message about it. */
    private int statementStart;
    /** The statement being read, once its keyword is known; null before. */
    private Statement current;
    /** Where the number that {@link #readNumber} read last starts. */
    private int tokenStart;
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
        this.source = source;
        this.bytes = source.bytes();
        this.end = end;
        this.part = part;
        this.pos = start;
        this.lineStart = start;
        this.line = firstLine;
        this.values = new GroupValues(source);
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
        if (namesMaterial) {
            part.addPending(values.copy());
        } else {
            statement.builder().build(values, output);
        }
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

    /** Reads {@code :(…)} into {@link #values}. */
    private void readGroup(Statement statement, Group group) throws StatementError {
        skipBlanks();
        if (!at(':')) {
            throw groupError(pos, "expected ':' before %s, found " + source.describe(pos, lineStart), statement, group);
        }
        pos++;
        skipBlanks();
        if (!at('(')) {
            throw groupError(pos, "expected '(' to start %s, found " + source.describe(pos, lineStart), statement, group);
        }
        int groupStart = pos++;
        values.openGroup(groupStart);
        skipBlanks();
        if (at(')') && group.kind() != Group.Kind.PROPERTIES) {
            throw groupError(groupStart, "empty group: %s needs " + contents(group), statement, group);
        }
        switch (group.kind()) {
            case NUMBERS -> readNumbers(statement, group, groupStart);
            case NAME -> readName(statement, group);
            case PATH -> readPath(statement, group);
            case PROPERTIES -> readProperties(statement, group);
        }
    }

    /** The numbers of a group, after its '(' and any blanks, up to and with its ')'. */
    private void readNumbers(Statement statement, Group group, int groupStart) throws StatementError {
        int found = 0;
        while (true) {
            skipBlanks();
            float value = readNumber();
            if (found == group.size()) {
                throw groupError(tokenStart, "too many numbers in %s: it takes " + contents(group), statement, group);
            }
            values.add(value, tokenStart, pos);
            found++;
            if (groupEndsAfterNumber(statement, group)) {
                break;
            }
        }
        if (found < group.size()) {
            throw groupError(groupStart, "too few numbers in %s: it takes " + contents(group) + ", found " + found,
                    statement, group);
        }
    }

    /** A name of letters, digits, '_' and '-', then blanks and the group's ')'. */
    private void readName(Statement statement, Group group) throws StatementError {
        int start = pos;
        while (pos < bytes.length && (ByteClasses.isWordByte(bytes[pos]) || bytes[pos] == '-')) {
            pos++;
        }
        if (pos == start) {
            throw groupError(pos, "expected a name in %s, found " + source.describe(pos, lineStart), statement, group);
        }
        values.addName(start, pos);
        int nameEnd = pos;
        skipBlanks();
        if (!at(')')) {
            throw error(pos, "expected ')' after '" + source.text(start, nameEnd) + "' in " + group.of(statement) + ", found "
                    + source.describe(pos, lineStart), "a name holds only letters, digits, '_' and '-'");
        }
        pos++;
    }

    /**
     * A path: everything up to the group's ')' on this line, blanks around it trimmed. A ':' with
     * a '(' after it ends it too: that is the next group, after a forgotten ')'.
     */
    private void readPath(Statement statement, Group group) throws StatementError {
        int start = pos;
        while (pos < bytes.length && bytes[pos] != ')' && !ByteClasses.isLineBreak(bytes[pos]) && !atNextGroup()) {
            pos++;
        }
        if (!at(')')) {
            throw groupError(pos, "expected ')' after the path in %s, found " + source.describe(pos, lineStart),
                    statement, group);
        }
        int nameEnd = pos;
        while (ByteClasses.isBlank(bytes[nameEnd - 1])) {
            nameEnd--; // the group is not empty, so a byte that is no blank stands before
        }
        values.addName(start, nameEnd);
        pos++;
    }

    /** {@code key=number} pairs separated by '|', up to and with the group's ')'; none is fine. */
    private void readProperties(Statement statement, Group group) throws StatementError {
        if (at(')')) {
            pos++;
            return;
        }
        while (true) {
            skipBlanks();
            int key = readKey(statement, group);
            skipBlanks();
            if (!at('=')) {
                throw groupError(pos, "expected '=' after the key '" + group.keys().get(key) + "' in %s, found "
                        + source.describe(pos, lineStart), statement, group);
            }
            pos++;
            skipBlanks();
            float value = readNumber();
            values.addProperty(key, value, tokenStart, pos);
            if (groupEndsAfterNumber(statement, group)) {
                return;
            }
        }
    }

    /** After a number: a '|' and more to come (false), or the group's ')' (true), each passed. */
    private boolean groupEndsAfterNumber(Statement statement, Group group) throws StatementError {
        skipBlanks();
        if (at('|') || at(')')) {
            return bytes[pos++] == ')';
        }
        throw groupError(pos, "expected '|' or ')' after a number in %s, found " + source.describe(pos, lineStart),
                statement, group);
    }

    /** A key of a properties group: its index among the group's keys; known and not given before. */
    private int readKey(Statement statement, Group group) throws StatementError {
        int start = pos;
        while (pos < bytes.length && ByteClasses.isWordByte(bytes[pos])) {
            pos++;
        }
        if (pos == start) {
            throw groupError(pos, "expected a key such as '" + group.keys().get(0) + "' in %s, found "
                    + source.describe(pos, lineStart), statement, group);
        }
        String word = source.text(start, pos);
        int key = group.keys().indexOf(word);
        if (key < 0) {
            String nearest = Suggestions.nearest(word, group.keys());
            throw error(start, "unknown key '" + word + "' in " + group.of(statement), nearest != null
                    ? "did you mean '" + nearest + "'?"
                    : "the keys are " + quotedList(group.keys()));
        }
        if (values.lastHasKey(key)) {
            throw error(start, "'" + word + "' is given twice in " + group.of(statement), "give each key once");
        }
        return key;
    }

    /** "'a', 'b' and 'c'". */
    private static String quotedList(List<String> words) {
        List<String> quoted = words.stream().map(w -> "'" + w + "'").toList();
        return String.join(", ", quoted.subList(0, quoted.size() - 1)) + " and " + quoted.get(quoted.size() - 1);
    }

    /** An error about a group; {@code %s} in the message becomes "the centre of 'sphere'". */
    private StatementError groupError(int offset, String message, Statement statement, Group group) {
        String text = message.replaceFirst(Pattern.quote("%s"), Matcher.quoteReplacement(group.of(statement))); // ours comes first
        return error(offset, text, "write it as " + statement.usage());
    }

    /** Reads one number token at {@link #pos}; its start is left in {@link #tokenStart}. */
    private float readNumber() throws StatementError {
        tokenStart = pos;
        while (pos < bytes.length && !ByteClasses.isDelimiter(bytes[pos])) {
            pos++;
        }
        if (pos == tokenStart) {
            throw error(pos, "expected a number, found " + source.describe(pos, lineStart), null);
        }
        try {
            return FloatParser.parse(bytes, tokenStart, pos);
        } catch (NumberFormatException e) {
            throw notANumber();
        }
    }

    /**
     * The error for the token just read, which is no number: at an invisible character that
     * starts it or follows a number (which {@link #error} names), else at the token, with a hint.
     */
    private StatementError notANumber() {
        int invisible = firstInvisible(tokenStart, pos);
        if (invisible == tokenStart) {
            return error(invisible, "expected a number, found " + source.describe(invisible, lineStart), null);
        }
        if (invisible > tokenStart && isNumber(tokenStart, invisible)) {
            return error(invisible, "expected '|' or ')' after a number, found " + source.describe(invisible, lineStart), null);
        }
        String token = source.text(tokenStart, pos);
        return error(tokenStart, "expected a number, found '" + token + "'", Hints.forNumber(token));
    }

    private boolean isNumber(int from, int to) {
        try {
            FloatParser.parse(bytes, from, to);
            return true;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    /** The offset of the first invisible character ({@link Hints#isInvisible}) in {@code bytes[from, to)}, or −1. */
    private int firstInvisible(int from, int to) {
        for (int i = from; i < to; i++) {
            if (bytes[i] < 0 && (bytes[i] & 0xC0) != 0x80 && Hints.isInvisible(source.codePointAt(i))) {
                return i;
            }
        }
        return -1;
    }

    /** What a group holds, for messages: "3 numbers (x|y|z)", "a name". */
    private static String contents(Group group) {
        return switch (group.kind()) {
            case NUMBERS -> group.size() == 1 ? "1 number (" + group.shape() + ")"
                    : group.size() + " numbers (" + group.shape() + ")";
            case NAME -> "a name";
            case PATH -> "a file path";
            case PROPERTIES -> "key=value pairs";
        };
    }

    // ---- bytes ---------------------------------------------------------------------------

    /** Where the statement being read stands, for a later message about it. */
    private SceneError located() {
        return new SceneError(source.name(), line, source.column(lineStart, statementStart), "", source.lineText(lineStart), null);
    }

    /** Whether {@link #pos} is at ':', blanks and '(': the start of a group. */
    private boolean atNextGroup() {
        if (bytes[pos] != ':') {
            return false;
        }
        int after = pos + 1;
        while (after < bytes.length && ByteClasses.isSpace(bytes[after])) {
            after++;
        }
        return after < bytes.length && bytes[after] == '(';
    }

    private boolean at(char c) {
        return pos < bytes.length && bytes[pos] == c;
    }

    /** Skips spaces and tabs, not a carriage return: it ends a line ({@link #skipToNextLine}). */
    private void skipBlanks() {
        while (pos < bytes.length && ByteClasses.isSpace(bytes[pos])) {
            pos++;
        }
    }

    private boolean atEndOfStatement() {
        return pos >= bytes.length || ByteClasses.isLineBreak(bytes[pos]) || atComment();
    }

    private boolean atComment() {
        return pos + 1 < bytes.length && bytes[pos] == '/' && bytes[pos + 1] == '/';
    }

    /** Goes past the next line break: LF, CR LF, or a CR alone, as old Mac files end lines. */
    private void skipToNextLine() {
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
    private StatementError error(int offset, String message, String help) {
        int codePoint = offset < bytes.length && bytes[offset] < 0 ? source.codePointAt(offset) : -1;
        return new StatementError(new SceneError(source.name(), line, source.column(lineStart, offset), message,
                source.lineText(lineStart), Hints.isInvisible(codePoint) ? Hints.forInvisible(codePoint) : help));
    }

    /** Hands what a statement makes to the part, with the statement's place where a later check needs it. */
    private final class PartOutput implements Statement.Output {

        @Override
        public void ambient(Color colour) {
            part.ambients.add(new ScenePart.Located<>(colour, located()));
        }

        @Override
        public void camera(ICamera camera) {
            part.cameras.add(new ScenePart.Located<>(camera, located()));
        }

        @Override
        public void light(Light light) {
            part.lights.add(light);
        }

        @Override
        public void object(IGeometry object) {
            part.objects.add(object);
        }

        @Override
        public void objects(List<IGeometry> objects) {
            part.objects.addAll(objects);
        }

        @Override
        public void material(String name, Material material) {
            part.materials.add(new ScenePart.Located<>(new ScenePart.Named(name, material), values.placeOfValue(0, 0)));
        }
    }
}
