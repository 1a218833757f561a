package rtd.io;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Sphere;
import rtd.io.Statement.Group;
import rtd.math.Vector3f;

/**
 * Reads the statements of a stretch of whole lines of a scene file into a {@link ScenePart}:
 * the syntax {@code keyword:(group):(group)…} of section 4.1 and the rules for the values.
 *
 * <p>Each mistake becomes a {@link SceneError} with line and column, and reading goes on with
 * the next line. It works on bytes, not on a String, and makes no object per number.
 */
final class StatementReader {

    private final SourceText source;
    private final byte[] bytes;
    private final int end;
    private final ScenePart part;
    private int pos;
    private int line;
    private int lineStart;

    /** The numbers of the statement being read, with where each stands. */
    private final StatementNumbers numbers;
    /** Where the number that {@link #readNumber} read last starts. */
    private int tokenStart;

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
        this.numbers = new StatementNumbers(source, this::error);
    }

    /** Reads every line, until the end or one error past {@link SceneParser#MAX_ERRORS}. */
    void readAll() {
        while (pos < end && part.errors.size() <= SceneParser.MAX_ERRORS) {
            try {
                readStatement();
            } catch (StatementError e) {
                part.errors.add(e.error);
            }
            skipToNextLine();
        }
    }

    // ---- one statement ------------------------------------------------------------------

    private void readStatement() throws StatementError {
        skipBlanks();
        if (atEndOfStatement()) {
            return; // a blank line or a comment
        }
        int keywordStart = pos;
        while (pos < bytes.length && ByteClasses.isWordByte(bytes[pos])) {
            pos++;
        }
        if (pos == keywordStart) {
            throw error(pos, "expected a statement (" + Statement.keywordList() + "), found " + source.describe(pos, lineStart), null);
        }
        Statement statement = Statement.find(bytes, keywordStart, pos);
        if (statement == null) {
            throw unknownKeyword(keywordStart);
        }
        part.statementCount++;
        int count = 0;
        for (int g = 0; g < statement.groups.size(); g++) { // no Iterator for each line of a large file
            count = readGroup(statement, statement.groups.get(g), count);
        }
        skipBlanks();
        if (at(':')) {
            throw error(pos, "too many groups: '" + statement.keyword + "' takes " + statement.groups.size(),
                    "write it as " + statement.usage());
        }
        if (!atEndOfStatement()) {
            throw error(pos, "expected the end of the line after the statement, found " + source.describe(pos, lineStart),
                    "a comment after a statement starts with //");
        }
        apply(statement, keywordStart);
    }

    private StatementError unknownKeyword(int keywordStart) {
        String word = source.text(keywordStart, pos);
        String nearest = Suggestions.nearestKeyword(word);
        String help = nearest != null
                ? "did you mean '" + nearest + "'?"
                : "a statement starts with " + Statement.keywordList();
        return error(keywordStart, "unknown statement '" + word + "'", help);
    }

    /** Reads {@code :(n|n|…)} into {@link #values} from {@code count} on; returns the new count. */
    private int readGroup(Statement statement, Group group, int count) throws StatementError {
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
        skipBlanks();
        if (at(')')) {
            throw groupError(groupStart, "empty group: %s needs " + numbers(group), statement, group);
        }
        int found = 0;
        while (true) {
            skipBlanks();
            float value = readNumber();
            if (found == group.size()) {
                throw groupError(tokenStart, "too many numbers in %s: it takes " + numbers(group), statement, group);
            }
            numbers.set(count + found, value, tokenStart, pos);
            found++;
            skipBlanks();
            if (at('|')) {
                pos++;
            } else if (at(')')) {
                pos++;
                break;
            } else {
                throw groupError(pos, "expected '|' or ')' after a number in %s, found " + source.describe(pos, lineStart), statement, group);
            }
        }
        if (found < group.size()) {
            throw groupError(groupStart, "too few numbers in %s: it takes " + numbers(group) + ", found " + found,
                    statement, group);
        }
        return count + found;
    }

    /** An error about a group; {@code %s} in the message becomes "the centre of 'sphere'". */
    private StatementError groupError(int offset, String message, Statement statement, Group group) {
        String what = "the " + group.meaning() + " of '" + statement.keyword + "'";
        String text = message.replaceFirst(Pattern.quote("%s"), Matcher.quoteReplacement(what)); // ours comes first
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
            String token = source.text(tokenStart, pos);
            throw error(tokenStart, "expected a number, found '" + token + "'", token.contains("\u2212")
                    ? "'\u2212' is a typographic minus sign (U+2212); type the plain '-' instead"
                    : "numbers are written like 3, -0.5, .5, 1. or 2e3");
        }
    }

    private static String numbers(Group group) {
        return group.size() == 1 ? "1 number (" + group.shape() + ")" : group.size() + " numbers (" + group.shape() + ")";
    }

    // ---- the meaning of a statement -----------------------------------------------------

    private void apply(Statement statement, int keywordStart) throws StatementError {
        switch (statement) {
            case AMBIENT -> part.ambients.add(new ScenePart.Located<>(numbers.colour(0), located(keywordStart)));
            case ORTHOGRAPHIC_CAMERA -> {
                Vector3f position = numbers.finiteVector(0, "position");
                Vector3f direction = numbers.viewDirection(3);
                float zoom = numbers.positive(6, "zoom");
                part.cameras.add(new ScenePart.Located<>(new OrthographicCamera(position, direction, zoom),
                        located(keywordStart)));
            }
            case SPHERE -> part.objects.add(new Sphere(numbers.finiteVector(0, "centre"), numbers.positive(3, "radius"),
                    numbers.colour(4)));
        }
    }

    /** Where a statement that starts at {@code offset} stands, for a later message about it. */
    private SceneError located(int offset) {
        return new SceneError(source.name(), line, source.column(lineStart, offset), "", source.lineText(lineStart), null);
    }

    private boolean at(char c) {
        return pos < bytes.length && bytes[pos] == c;
    }

    private void skipBlanks() {
        while (pos < bytes.length && ByteClasses.isBlank(bytes[pos])) {
            pos++;
        }
    }

    private boolean atEndOfStatement() {
        return pos >= bytes.length || bytes[pos] == '\n' || atComment();
    }

    private boolean atComment() {
        return pos + 1 < bytes.length && bytes[pos] == '/' && bytes[pos + 1] == '/';
    }

    private void skipToNextLine() {
        while (pos < end && bytes[pos] != '\n') {
            pos++;
        }
        if (pos < end) {
            pos++;
            line++;
            lineStart = pos;
        }
    }

    StatementError error(int offset, String message, String help) {
        SceneError error = new SceneError(source.name(), line, source.column(lineStart, offset), message,
                source.lineText(lineStart), help);
        return new StatementError(error);
    }

    /** Ends the reading of one statement; the reader records the error and goes on. */
    static final class StatementError extends Exception {
        private static final long serialVersionUID = 1L;
        private final transient SceneError error;

        StatementError(SceneError error) {
            super(error.message(), null, false, false);
            this.error = error;
        }
    }
}
