package rtd.io;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads the groups of a statement, {@code :(…)} each, into {@link GroupValues}: numbers separated
 * by '|', a name, a file path, or {@code key=number} properties, as the statement's
 * {@link Group}s say; and words each mistake in them at its place, with the statement's usage or
 * a hint. {@link StatementReader}, which reads the keyword and the rest of the line, is the one
 * kind of it; its position on the line is the {@link LineCursor} it extends.
 */
abstract sealed class GroupReader extends LineCursor permits StatementReader {

    final GroupValues values;
    /** Where the number that {@link #readNumber} read last starts. */
    private int tokenStart;

    GroupReader(SourceText source, int start, int end, int firstLine) {
        super(source, start, end, firstLine);
        this.values = new GroupValues(source);
    }

    /** Reads {@code :(…)} into {@link #values}. */
    final void readGroup(Statement statement, Group group) throws StatementError {
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
                throw tooManyNumbers(statement, group, groupStart);
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
                    + source.describe(pos, lineStart), nameHint(group, start));
        }
        pos++;
    }

    /**
     * The help for a name followed by something else. Properties where a name belongs get their
     * own: written where an object names its material ({@code sphere:…:(reflective=0.5)}), a
     * material is defined on a line of its own and named there; written first in a
     * {@code material} ({@code material:(reflective=0.5)}), its name comes first.
     */
    private String nameHint(Group group, int start) {
        if (!at('=')) {
            return "a name holds only letters, digits, '_' and '-'";
        }
        int end = start;
        while (end < bytes.length && bytes[end] != ')' && !ByteClasses.isLineBreak(bytes[end])) {
            end++;
        }
        String properties = source.text(start, end).strip();
        return group == Statement.MATERIAL
                ? "an object names its material here; define the material on a line of its own, such as "
                        + "material:(shiny):(" + properties + "), then write (shiny) here"
                : "a material's name comes first, then its properties: material:(shiny):(" + properties + ")";
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

    /**
     * Too many numbers in a group. Where the line has fewer groups than the statement takes from
     * this one on, the likelier mistake is this group left out (its numbers are the next group's),
     * and the hint says so: {@code sphere:(3|8|-1):(0|127|255)} lacks its radius.
     */
    private StatementError tooManyNumbers(Statement statement, Group group, int groupStart) {
        String message = "too many numbers in %s: it takes " + contents(group);
        int g = statement.groups().indexOf(group);
        if (g < 0 || groupsOnTheLineFrom(groupStart) >= statement.groups().size() - g) {
            return groupError(tokenStart, message, statement, group);
        }
        String text = message.replaceFirst(Pattern.quote("%s"), Matcher.quoteReplacement(group.of(statement)));
        return error(tokenStart, text, "this line has fewer groups than '" + statement.keyword() + "' takes: was the "
                + group.meaning() + " left out before this group? write it as " + statement.usage());
    }

    /** The groups that open on the line from {@code offset} on, up to its end or a comment: a count for a hint only. */
    private int groupsOnTheLineFrom(int offset) {
        int groups = 0;
        for (int i = offset; i < bytes.length && bytes[i] != '\n' && bytes[i] != '\r'; i++) {
            if (bytes[i] == '/' && i + 1 < bytes.length && bytes[i + 1] == '/') {
                break;
            }
            groups += bytes[i] == '(' ? 1 : 0;
        }
        return groups;
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
            boolean emptyPlace = pos < bytes.length && (bytes[pos] == '|' || bytes[pos] == ')');
            throw error(pos, "expected a number, found " + source.describe(pos, lineStart),
                    emptyPlace ? "a number is missing here: each place between '(', '|' and ')' holds one" : null);
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
}
