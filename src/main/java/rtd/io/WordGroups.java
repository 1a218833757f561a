package rtd.io;

/**
 * The groups of Part III that hold a word where the paper's hold numbers, for the {@link GroupReader}: an
 * object's colour written as a pattern's name, {@code (tiles)}, and a transformation's step, a word and its
 * numbers, {@code (rotate_y 30)}.
 */
final class WordGroups {

    private WordGroups() {
    }

    /** Whether the group holds one name from the cursor on: a letter first, then a word, blanks and ')'. */
    static boolean atLoneName(LineCursor cursor) {
        byte[] bytes = cursor.bytes;
        int p = cursor.pos;
        if (p >= bytes.length || !Character.isLetter(bytes[p])) {
            return false;
        }
        while (p < bytes.length && (TextBytes.isWordByte(bytes[p]) || bytes[p] == '-')) {
            p++;
        }
        while (p < bytes.length && TextBytes.isBlank(bytes[p])) {
            p++;
        }
        return p < bytes.length && bytes[p] == ')';
    }

    /** A step of a transformation: a word, blanks, and one or more numbers separated by '|', up to and with ')'. */
    static void readStep(GroupReader reader, LineCursor cursor, WrittenGroups written, Statement statement, Group group)
            throws StatementError {
        int start = cursor.pos;
        while (cursor.pos < cursor.bytes.length && TextBytes.isWordByte(cursor.bytes[cursor.pos])) {
            cursor.pos++;
        }
        if (cursor.pos == start) {
            throw reader.groupError(cursor.pos, "expected an operation such as 'scale 2' in %s, found " + cursor.describe(cursor.pos),
                    statement, group);
        }
        written.add(Float.NaN, start, cursor.pos);
        cursor.skipBlanks();
        if (cursor.at(')')) {
            throw cursor.error(cursor.pos, "expected numbers after '" + cursor.source.text(start, cursor.pos).strip()
                    + "' in " + group.of(statement) + ", found ')'", "write a step as (scale 2), (scale 1|2|1), (rotate_y 30) or (translate 0|1|0)");
        }
        while (true) {
            cursor.skipBlanks();
            reader.readNumberInto();
            if (reader.groupEndsAfterNumber(statement, group)) {
                return;
            }
        }
    }
}
