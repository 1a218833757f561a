package rtd.io;

/**
 * Reads a statement's groups {@code :(…)} into its {@link StatementValues} as its {@link Group}s say: the
 * paper's numbers, and Part III's words where numbers may stand ({@code (tiles)}, {@code (rotate_y 30)}).
 * Each mistake is worded at its place, with the usage or a hint.
 */
final class GroupReader {

    private final LineCursor cursor;
    private final StatementValues values;
    private final NumberReader numbers;
    private Statement statement;
    private Group group;

    GroupReader(LineCursor cursor, StatementValues values, Names names) {
        this.cursor = cursor;
        this.values = values;
        this.numbers = new NumberReader(cursor, names, values);
    }

    void readGroup(Statement statement, Group group) throws SceneException {
        this.statement = statement;
        this.group = group;
        pass(':', "':' before ");
        pass('(', "'(' to start ");
        int groupStart = cursor.pos - 1;
        values.openGroup(groupStart);
        cursor.skipBlanks();
        if (cursor.at(')') && group.rule() == Group.Rule.PROPERTIES) {
            cursor.pos++; // no properties: the default finish
            return;
        }
        if (cursor.at(')')) {
            throw groupError(groupStart, "empty group: " + group.of(statement) + " needs " + group.contents());
        }
        boolean patternName = group.rule() == Group.Rule.PAINT && atLoneName();
        values.patternGroup = patternName ? values.groupCount() - 1 : values.patternGroup;
        switch (patternName ? Group.Rule.NAME : group.rule()) {
            case NAME -> readName();
            case PATH -> readPath();
            case STEP -> {
                readStepWord();
                readNumbers(groupStart);
            }
            default -> readNumbers(groupStart);
        }
    }

    /** Numbers separated by '|' up to and with the ')': perhaps {@code (at x|y|z)}, or each after a key and '='. */
    private void readNumbers(int groupStart) throws SceneException {
        byte[] bytes = cursor.bytes;
        int p = cursor.pos;
        boolean target = group.rule() == Group.Rule.VIEW && p + 2 < bytes.length && bytes[p] == 'a'
                && bytes[p + 1] == 't' && TextBytes.isSpace(bytes[p + 2]);
        if (target) {
            cursor.pos += 2;
            values.target = values.groupCount() - 1;
        }
        boolean counted = group.rule() != Group.Rule.PROPERTIES && group.rule() != Group.Rule.STEP;
        numbers.group = group;
        numbers.statement = statement;
        int found = 0;
        do {
            cursor.skipBlanks();
            numbers.readAndKeep(group.rule() == Group.Rule.PROPERTIES ? readKey() : -1);
            if (++found > group.size() && counted) {
                throw tooManyNumbers(groupStart);
            }
        } while (!groupEndsAfterNumber());
        if (found < group.size() && target) {
            throw cursor.error(groupStart, "too few numbers in the point that '" + statement.keyword()
                    + "' looks at: it takes 3 numbers (at x|y|z), found " + found, "write the point as (at x|y|z)");
        }
        if (found < group.size()) {
            throw groupError(groupStart, "too few numbers in " + group.of(statement) + ": it takes " + group.contents()
                    + ", found " + found);
        }
    }

    /** Whether the group holds one name from the cursor on: a letter first, then a word, blanks and ')'. */
    private boolean atLoneName() {
        byte[] bytes = cursor.bytes;
        if (cursor.pos >= bytes.length || !Character.isLetter(bytes[cursor.pos])) {
            return false;
        }
        int p = afterName(cursor.pos);
        while (p < bytes.length && TextBytes.isBlank(bytes[p])) {
            p++;
        }
        return p < bytes.length && bytes[p] == ')';
    }

    /** The word that starts a transformation's step, then blanks: numbers follow. */
    private void readStepWord() throws SceneException {
        int start = cursor.pos;
        cursor.pos = cursor.afterWord(start);
        if (cursor.pos == start) {
            throw expected("an operation such as 'scale 2' in ");
        }
        values.add(Float.NaN, start, cursor.pos, -1);
        cursor.skipBlanks();
        if (cursor.at(')')) {
            throw cursor.error(cursor.pos, "expected numbers after '" + cursor.source.text(start, cursor.pos).strip()
                    + "' in " + group.of(statement) + ", found ')'", Names.STEP_HELP);
        }
    }

    private void readName() throws SceneException {
        int start = cursor.pos;
        cursor.pos = afterName(start);
        if (cursor.pos == start) {
            throw expected("a name in ");
        }
        values.add(Float.NaN, start, cursor.pos, -1);
        int nameEnd = cursor.pos;
        cursor.skipBlanks();
        if (!cursor.at(')')) {
            throw cursor.error(cursor.pos, "expected ')' after '" + cursor.source.text(start, nameEnd) + "' in "
                    + group.of(statement) + ", found " + cursor.describe(cursor.pos),
                    Hints.forName(cursor, group, start));
        }
        cursor.pos++;
    }

    /** The offset after the name (letters, digits, '_' and '-') from {@code from}; {@code from} if none. */
    private int afterName(int from) {
        int p = from;
        while (p < cursor.bytes.length && (TextBytes.isWordByte(cursor.bytes[p]) || cursor.bytes[p] == '-')) {
            p++;
        }
        return p;
    }

    /** A path: up to the group's ')' on this line, trimmed; or up to the next group's ':(' after a forgotten ')'. */
    private void readPath() throws SceneException {
        int start = cursor.pos;
        byte[] bytes = cursor.bytes;
        while (cursor.pos < bytes.length && bytes[cursor.pos] != ')' && !TextBytes.isLineBreak(bytes[cursor.pos])
                && !cursor.atNextGroup()) {
            cursor.pos++;
        }
        if (!cursor.at(')')) {
            throw expected("')' after the path in ");
        }
        int nameEnd = cursor.pos;
        while (TextBytes.isBlank(bytes[nameEnd - 1])) {
            nameEnd--; // the group is not empty, so a byte that is no blank stands before
        }
        values.add(Float.NaN, start, nameEnd, -1);
        cursor.pos++;
    }

    /** After a number: a '|' and more to come (false), or the group's ')' (true), each passed. */
    private boolean groupEndsAfterNumber() throws SceneException {
        cursor.skipBlanks();
        if (cursor.at('|') || cursor.at(')')) {
            return cursor.bytes[cursor.pos++] == ')';
        }
        throw expected("'|' or ')' after a number in ");
    }

    /** A property's key and its '=': the key's index in {@link Group#KEYS}. */
    private int readKey() throws SceneException {
        int start = cursor.pos;
        cursor.pos = cursor.afterWord(start);
        if (cursor.pos == start) {
            throw expected("a key such as '" + Group.KEYS.get(0) + "' in ");
        }
        String word = cursor.source.text(start, cursor.pos);
        int key = Group.KEYS.indexOf(word);
        if (key < 0) {
            throw cursor.error(start, "unknown key '" + word + "' in " + group.of(statement),
                    Hints.nearestOrList(word, Group.KEYS, "keys"));
        }
        if (values.lastHasKey(key)) {
            throw cursor.error(start, "'" + word + "' is given twice in " + group.of(statement), "give each key once");
        }
        pass('=', "'=' after the key '" + word + "' in ");
        cursor.skipBlanks();
        return key;
    }

    /** Goes past blanks and {@code c}, which must stand there. */
    private void pass(char c, String what) throws SceneException {
        cursor.skipBlanks();
        if (!cursor.at(c)) {
            throw expected(what);
        }
        cursor.pos++;
    }

    /** Too many numbers in a group; on a line with too few groups the hint says this group was likely left out. */
    private SceneException tooManyNumbers(int groupStart) {
        String message = "too many numbers in " + group.of(statement) + ": it takes " + group.contents();
        // only a statement's own groups hold counted numbers, so the group is one of them
        if (groupsOnTheLineFrom(groupStart) >= statement.groups().size() - (values.groupCount() - 1)) {
            return groupError(numbers.tokenStart, message);
        }
        return cursor.error(numbers.tokenStart, message, "this line has fewer groups than '" + statement.keyword()
                + "' takes: was the " + group.meaning() + " left out before this group? write it as "
                + statement.usage());
    }

    /** The groups that open from {@code offset} to the line's end or comment, for a hint only. */
    private int groupsOnTheLineFrom(int offset) {
        int groups = 0;
        byte[] bytes = cursor.bytes;
        for (int i = offset; i < bytes.length && !TextBytes.isLineBreak(bytes[i]); i++) {
            if (bytes[i] == '/' && i + 1 < bytes.length && bytes[i + 1] == '/') {
                break;
            }
            groups += bytes[i] == '(' ? 1 : 0;
        }
        return groups;
    }

    /** "expected {@code what} the centre of 'sphere', found …" at the cursor, with the usage as the help. */
    private SceneException expected(String what) {
        return groupError(cursor.pos, "expected " + what + group.of(statement) + ", found "
                + cursor.describe(cursor.pos));
    }

    private SceneException groupError(int offset, String message) {
        return cursor.error(offset, message, "write it as " + statement.usage());
    }
}
