package rtd.io;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Sphere;
import rtd.io.Statement.Group;
import rtd.math.Vector3f;
import rtd.scene.Color;

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

    /** The numbers of the statement being read, with where each starts and ends. */
    private final float[] values = new float[8];
    private final int[] valueStarts = new int[8];
    private final int[] valueEnds = new int[8];
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
        for (Group group : statement.groups) {
            count = readGroup(statement, group, count);
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
            values[count + found] = value;
            valueStarts[count + found] = tokenStart;
            valueEnds[count + found] = pos;
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
            case AMBIENT -> part.ambients.add(new ScenePart.Located<>(colour(0), located(keywordStart)));
            case ORTHOGRAPHIC_CAMERA -> {
                Vector3f position = finiteVector(0, "position");
                Vector3f direction = viewDirection(3);
                float zoom = positive(6, "zoom");
                part.cameras.add(new ScenePart.Located<>(new OrthographicCamera(position, direction, zoom),
                        located(keywordStart)));
            }
            case SPHERE -> part.objects.add(new Sphere(finiteVector(0, "centre"), positive(3, "radius"), colour(4)));
        }
    }

    /** Where a statement that starts at {@code offset} stands, for a later message about it. */
    private SceneError located(int offset) {
        return new SceneError(source.name(), line, source.column(lineStart, offset), "", source.lineText(lineStart), null);
    }

    private float finite(int i, String name) throws StatementError {
        float value = values[i];
        if (Float.isFinite(value)) {
            return value;
        }
        String written = source.text(valueStarts[i], valueEnds[i]);
        boolean overflow = !written.contains("NaN") && !written.contains("Infinity");
        throw error(valueStarts[i], "the " + name + " must be a finite number, found " + written
                + (overflow ? ", which is too large for a float" : ""),
                overflow ? "a float holds numbers up to about 3.4e38" : null);
    }

    /** The three numbers from {@code i} on as a vector; {@code name} is only read for a message. */
    private Vector3f finiteVector(int i, String name) throws StatementError {
        for (int k = 0; k < 3; k++) {
            if (!Float.isFinite(values[i + k])) {
                finite(i + k, "xyz".charAt(k) + " of the " + name);
            }
        }
        return new Vector3f(values[i], values[i + 1], values[i + 2]);
    }

    private float positive(int i, String name) throws StatementError {
        float value = finite(i, name);
        if (value > 0) {
            return value;
        }
        throw error(valueStarts[i], "the " + name + " must be greater than 0, found " + source.text(valueStarts[i], valueEnds[i]), null);
    }

    private Vector3f viewDirection(int i) throws StatementError {
        Vector3f direction = finiteVector(i, "view direction");
        float squaredLength = direction.dot(direction);
        if (direction.x() == 0 && direction.y() == 0 && direction.z() == 0) {
            throw error(valueStarts[i], "the view direction must not be zero, found " + groupText(i, 3),
                    "the camera looks along it; (0|0|-1) looks into the screen");
        }
        if (!(squaredLength >= Float.MIN_NORMAL) || Float.isInfinite(squaredLength)) {
            throw error(valueStarts[i], "the view direction " + groupText(i, 3) + " is too "
                    + (Float.isInfinite(squaredLength) ? "long" : "short") + " to compute with in float",
                    "only its direction matters: scale it to a length near 1");
        }
        return direction;
    }

    private Color colour(int i) throws StatementError {
        int[] channels = new int[3];
        String[] names = {"red", "green", "blue"};
        for (int k = 0; k < 3; k++) {
            float value = values[i + k];
            if (!(value >= 0 && value <= 255 && value == Math.rint(value))) {
                throw error(valueStarts[i + k], "the " + names[k] + " channel must be a whole number from 0 to 255, found "
                        + source.text(valueStarts[i + k], valueEnds[i + k]), null);
            }
            channels[k] = (int) value;
        }
        return new Color(channels[0], channels[1], channels[2]);
    }

    private String groupText(int i, int size) {
        StringBuilder text = new StringBuilder("(");
        for (int k = 0; k < size; k++) {
            text.append(k > 0 ? "|" : "").append(source.text(valueStarts[i + k], valueEnds[i + k]));
        }
        return text.append(')').toString();
    }

    // ---- reading bytes ------------------------------------------------------------------

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

    private StatementError error(int offset, String message, String help) {
        SceneError error = new SceneError(source.name(), line, source.column(lineStart, offset), message,
                source.lineText(lineStart), help);
        return new StatementError(error);
    }

    /** Ends the reading of one statement; the parser records the error and goes on. */
    private static final class StatementError extends Exception {
        private static final long serialVersionUID = 1L;
        private final transient SceneError error;

        StatementError(SceneError error) {
            super(error.message(), null, false, false);
            this.error = error;
        }
    }
}
