package rtd.io;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.io.Statement.Group;
import rtd.math.Vector3f;
import rtd.scene.Color;
import rtd.scene.Scene;

/**
 * Reads the scene format of the paper (section 4.1, Listing A.1) from a file's bytes.
 *
 * <p>One statement a line: {@code keyword:(group):(group)…}, a group being numbers separated
 * by {@code |}. {@code //} starts a comment; blank lines, spaces and tabs around any token,
 * Windows line ends and a UTF-8 byte-order mark are all fine. Each mistake becomes a
 * {@link SceneError} with line and column; the parser goes on with the next line, so that one
 * run reports every mistake in the file, up to {@value #MAX_ERRORS}.
 *
 * <p>It works on bytes, not on a String, and makes no object per number: a scene of a million
 * spheres is 55 MB of text.
 */
final class SceneParser {

    /** After this many errors the parser stops; more would only scroll the first ones away. */
    static final int MAX_ERRORS = 20;

    private static final String CAMERA_EXAMPLE = "orthographic_camera:(0|0|20):(0|0|-1):(50)";

    private final SourceText source;
    private final byte[] bytes;
    private int pos;
    private int line = 1;
    private int lineStart;
    private final List<SceneError> errors = new ArrayList<>();

    /** The numbers of the statement being read, with where each starts and ends. */
    private final float[] values = new float[8];
    private final int[] valueStarts = new int[8];
    private final int[] valueEnds = new int[8];
    /** Where the number that {@link #readNumber} read last starts. */
    private int tokenStart;

    private int statementCount;
    private Color ambient;
    private int ambientLine;
    private ICamera camera;
    private int cameraLine;
    private final List<IGeometry> objects = new ArrayList<>();

    private SceneParser(SourceText source) {
        this.source = source;
        this.bytes = source.bytes();
    }

    /** Reads a scene, or throws every mistake found in it. */
    static Scene parse(SourceText source) throws SceneException {
        return new SceneParser(source).parse();
    }

    private Scene parse() throws SceneException {
        if (checkIsText()) {
            skipByteOrderMark();
            while (pos < bytes.length && errors.size() < MAX_ERRORS) {
                try {
                    readStatement();
                } catch (StatementError e) {
                    errors.add(e.error);
                }
                skipToNextLine();
            }
            checkWholeScene();
        }
        if (!errors.isEmpty()) {
            throw new SceneException(errors, errors.size() >= MAX_ERRORS && pos < bytes.length);
        }
        return new Scene(ambient != null ? ambient : Color.BLACK, camera, objects);
    }

    // ---- the file as a whole ------------------------------------------------------------

    /** Records an error and returns false if the bytes are not UTF-8 text. */
    private boolean checkIsText() {
        int bad = firstNonTextByte();
        if (bad < 0) {
            return true;
        }
        int badLine = 1;
        int badLineStart = 0;
        for (int i = 0; i < bad; i++) {
            if (bytes[i] == '\n') {
                badLine++;
                badLineStart = i + 1;
            }
        }
        String what = bytes[bad] == 0 ? "a NUL byte" : String.format("byte 0x%02X, which is not UTF-8", bytes[bad] & 0xFF);
        errors.add(new SceneError(source.name(), badLine, source.column(badLineStart, bad),
                "this is not a text file: found " + what, null, "a scene is a text file, such as examples/input_rtd.txt"));
        return false;
    }

    /** The offset of the first NUL byte or invalid UTF-8 sequence, or −1. */
    private int firstNonTextByte() {
        boolean ascii = true;
        for (int i = 0; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                return i;
            }
            ascii &= bytes[i] > 0;
        }
        if (ascii) {
            return -1;
        }
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CoderResult result = decoder.decode(in, CharBuffer.allocate(bytes.length), true);
        return result.isError() ? in.position() : -1;
    }

    private void skipByteOrderMark() {
        if (bytes.length >= 3 && (bytes[0] & 0xFF) == 0xEF && (bytes[1] & 0xFF) == 0xBB && (bytes[2] & 0xFF) == 0xBF) {
            pos = 3;
            lineStart = 3;
        }
    }

    private void checkWholeScene() {
        if (!errors.isEmpty()) {
            return; // a broken camera line would also read as "no camera": say it once
        }
        if (statementCount == 0) {
            errors.add(errorAtStart("the scene is empty: it has no statements, only blanks and comments",
                    "a scene needs at least a camera, such as " + CAMERA_EXAMPLE));
        } else if (camera == null) {
            errors.add(errorAtStart("the scene has no camera", "add a line such as " + CAMERA_EXAMPLE));
        }
    }

    private SceneError errorAtStart(String message, String help) {
        int start = bytes.length >= 3 && (bytes[0] & 0xFF) == 0xEF ? 3 : 0;
        return new SceneError(source.name(), 1, 1, message, source.lineText(start), help);
    }

    // ---- one statement ------------------------------------------------------------------

    private void readStatement() throws StatementError {
        skipBlanks();
        if (atEndOfStatement()) {
            return; // a blank line or a comment
        }
        int keywordStart = pos;
        while (pos < bytes.length && isWordByte(bytes[pos])) {
            pos++;
        }
        if (pos == keywordStart) {
            throw error(pos, "expected a statement (" + Statement.keywordList() + "), found " + describe(pos), null);
        }
        Statement statement = Statement.find(bytes, keywordStart, pos);
        if (statement == null) {
            throw unknownKeyword(keywordStart);
        }
        statementCount++;
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
            throw error(pos, "expected the end of the line after the statement, found " + describe(pos),
                    "a comment after a statement starts with //");
        }
        apply(statement, keywordStart);
    }

    private StatementError unknownKeyword(int keywordStart) {
        String word = text(keywordStart, pos);
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
            throw groupError(pos, "expected ':' before %s, found " + describe(pos), statement, group);
        }
        pos++;
        skipBlanks();
        if (!at('(')) {
            throw groupError(pos, "expected '(' to start %s, found " + describe(pos), statement, group);
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
                throw groupError(pos, "expected '|' or ')' after a number in %s, found " + describe(pos), statement, group);
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
        while (pos < bytes.length && !isDelimiter(bytes[pos])) {
            pos++;
        }
        if (pos == tokenStart) {
            throw error(pos, "expected a number, found " + describe(pos), null);
        }
        try {
            return FloatParser.parse(bytes, tokenStart, pos);
        } catch (NumberFormatException e) {
            String token = text(tokenStart, pos);
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
            case AMBIENT -> {
                Color colour = colour(0);
                if (ambient != null) {
                    throw error(keywordStart, "a second 'ambient': a scene has one background colour",
                            "the first 'ambient' is at line " + ambientLine);
                }
                ambient = colour;
                ambientLine = line;
            }
            case ORTHOGRAPHIC_CAMERA -> {
                Vector3f position = finiteVector(0, "position");
                Vector3f direction = viewDirection(3);
                float zoom = positive(6, "zoom");
                if (camera != null) {
                    throw error(keywordStart, "a second camera: a scene has one",
                            "the first camera is at line " + cameraLine);
                }
                camera = new OrthographicCamera(position, direction, zoom);
                cameraLine = line;
            }
            case SPHERE -> objects.add(new Sphere(finiteVector(0, "centre"), positive(3, "radius"), colour(4)));
        }
    }

    private float finite(int i, String name) throws StatementError {
        float value = values[i];
        if (Float.isFinite(value)) {
            return value;
        }
        String written = text(valueStarts[i], valueEnds[i]);
        boolean overflow = !written.contains("NaN") && !written.contains("Infinity");
        throw error(valueStarts[i], "the " + name + " must be a finite number, found " + written
                + (overflow ? ", which is too large for a float" : ""),
                overflow ? "a float holds numbers up to about 3.4e38" : null);
    }

    private Vector3f finiteVector(int i, String name) throws StatementError {
        return new Vector3f(finite(i, "x of the " + name), finite(i + 1, "y of the " + name), finite(i + 2, "z of the " + name));
    }

    private float positive(int i, String name) throws StatementError {
        float value = finite(i, name);
        if (value > 0) {
            return value;
        }
        throw error(valueStarts[i], "the " + name + " must be greater than 0, found " + text(valueStarts[i], valueEnds[i]), null);
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
                        + text(valueStarts[i + k], valueEnds[i + k]), null);
            }
            channels[k] = (int) value;
        }
        return new Color(channels[0], channels[1], channels[2]);
    }

    private String groupText(int i, int size) {
        StringBuilder text = new StringBuilder("(");
        for (int k = 0; k < size; k++) {
            text.append(k > 0 ? "|" : "").append(text(valueStarts[i + k], valueEnds[i + k]));
        }
        return text.append(')').toString();
    }

    // ---- reading bytes ------------------------------------------------------------------

    private boolean at(char c) {
        return pos < bytes.length && bytes[pos] == c;
    }

    private void skipBlanks() {
        while (pos < bytes.length && isBlank(bytes[pos])) {
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
        while (pos < bytes.length && bytes[pos] != '\n') {
            pos++;
        }
        if (pos < bytes.length) {
            pos++;
            line++;
            lineStart = pos;
        }
    }

    private static boolean isBlank(byte b) {
        return b == ' ' || b == '\t' || b == '\r' || b == '\f' || b == 0x0B;
    }

    private static boolean isWordByte(byte b) {
        return (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || b == '_';
    }

    private static boolean isDelimiter(byte b) {
        return b == '|' || b == ')' || b == '(' || b == ':' || b == '\n' || isBlank(b);
    }

    private String text(int start, int end) {
        return new String(bytes, start, end - start, StandardCharsets.UTF_8);
    }

    /** What stands at {@code offset}, for "found …" in a message. */
    private String describe(int offset) {
        if (offset >= bytes.length) {
            return offset > lineStart ? "the end of the line" : "the end of the file";
        }
        if (bytes[offset] == '\n' || bytes[offset] == '\r' && offset + 1 < bytes.length && bytes[offset + 1] == '\n') {
            return "the end of the line";
        }
        if (offset + 1 < bytes.length && bytes[offset] == '/' && bytes[offset + 1] == '/') {
            return "a comment";
        }
        int end = offset + 1;
        if (isWordByte(bytes[offset])) {
            while (end < bytes.length && isWordByte(bytes[end])) {
                end++; // show a whole word, not its first letter
            }
        }
        while (end < bytes.length && (bytes[end] & 0xC0) == 0x80) {
            end++; // the rest of a character of several bytes
        }
        int codePoint = text(offset, end).codePointAt(0);
        return Character.isISOControl(codePoint)
                ? String.format("the control character U+%04X", codePoint)
                : "'" + text(offset, end) + "'";
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
