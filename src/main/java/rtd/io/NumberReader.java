package rtd.io;

import java.util.Locale;
import rtd.scene.SceneWarnings;

/**
 * Reads one number of a group: a plain number as the paper's scenes have, by {@link FloatParser}, or an expression
 * (Part III), evaluated in double precision at the reading's clock and rounded to float once. Only a value that is
 * no plain number goes to the {@link ExpressionParser}, so plain numbers read fast and keep their messages.
 */
final class NumberReader {

    private final LineCursor cursor;
    private final Names names;
    private final StatementValues values;
    /** Made at the first value that is no plain number: a file of plain numbers never loads it. */
    private ExpressionParser expressions;
    int tokenStart;
    /** The group read, and its statement, for a message's hint. */
    Group group;
    Statement statement;
    /** The expression read last, and its value in double precision; null for a plain number. */
    private Expression tree;
    private double exact;

    NumberReader(LineCursor cursor, Names names, StatementValues values) {
        this.cursor = cursor;
        this.names = names;
        this.values = values;
    }

    private ExpressionParser expressions() {
        expressions = expressions != null ? expressions : new ExpressionParser(cursor, names);
        return expressions;
    }

    /** Reads one number, or an expression, at the cursor, and keeps it in the values with {@code key} (or −1). */
    void readAndKeep(int key) throws SceneException {
        float value = read();
        values.add(value, tokenStart, cursor.pos, key);
        if (tree != null) {
            values.markExpression(exact, tree);
        }
    }

    /** One number or expression at the cursor. The common case, a plain number before '|' or ')', stays small. */
    private float read() throws SceneException {
        tree = null;
        int start = cursor.pos;
        tokenStart = start;
        byte[] bytes = cursor.bytes;
        long plain = FloatParser.leading(bytes, start, bytes.length);
        int end = (int) (plain >>> 32);
        if (end > start && end < bytes.length && (bytes[end] == '|' || bytes[end] == ')')) {
            cursor.pos = end;
            return Float.intBitsToFloat((int) plain);
        }
        end = start; // an expression or a mistake: the token is all up to a delimiter
        while (end < bytes.length && !TextBytes.isDelimiter(bytes[end])) {
            end++;
        }
        cursor.pos = end;
        return readOther();
    }

    /** A token that is no plain number before '|' or ')': one before blanks, an expression, or a mistake. */
    private float readOther() throws SceneException {
        if (cursor.pos > tokenStart) {
            try {
                float plain = FloatParser.parse(cursor.bytes, tokenStart, cursor.pos);
                if (!operatorFollows()) {
                    return plain;
                }
            } catch (NumberFormatException e) {
                if (!looksLikeExpression()) {
                    throw notANumber();
                }
            }
        } else if (!cursor.at('(')) {
            boolean emptyPlace = cursor.at('|') || cursor.at(')');
            throw cursor.error(cursor.pos, "expected a number, found " + cursor.describe(cursor.pos),
                    emptyPlace ? "a number is missing here: each place between '(', '|' and ')' holds one" : null);
        }
        return expression();
    }

    /** The expression from {@link #tokenStart}: its value at the clock, finite and within a float's range. */
    private float expression() throws SceneException {
        cursor.pos = tokenStart;
        Expression read = expressions().read();
        String text = cursor.source.text(tokenStart, cursor.pos);
        String at = read.usesClock() ? " at clock = " + SceneWarnings.number(names.clock) : "";
        try {
            exact = read.value(names.clock);
        } catch (Expression.NotFinite e) {
            String part = e.why != null ? e.why : "is " + (Double.isNaN(e.value) ? "not a number (NaN)" : "infinite");
            int place = e.part instanceof Expression.Operation operation ? operation.opOffset() : e.part.start();
            throw cursor.error(place, "'" + text + "' is not a finite number" + at + ": this part of it " + part,
                    "a division by 0, the square root of a number below 0, or asin or acos of a number beyond -1 "
                            + "to 1 have no value");
        }
        float value = (float) exact;
        if (Float.isInfinite(value)) {
            throw cursor.error(tokenStart, "'" + text + "' is too large for a float" + at, Hints.FLOAT_RANGE);
        }
        tree = read;
        return value;
    }

    private boolean operatorFollows() {
        int p = cursor.pos;
        byte[] bytes = cursor.bytes;
        while (p < bytes.length && TextBytes.isSpace(bytes[p])) {
            p++;
        }
        byte b = p < bytes.length ? bytes[p] : 0;
        boolean comment = b == '/' && p + 1 < bytes.length && bytes[p + 1] == '/';
        return b == '+' || b == '-' || b == '*' || b == '^' || b == '/' && !comment;
    }

    /**
     * Whether the token that is no plain number is meant as an expression: it calls a function, holds an operator,
     * or (nearly) names a value; else it keeps the message of a mistyped number ({@code 2,5}, {@code eight}).
     */
    private boolean looksLikeExpression() {
        byte[] bytes = cursor.bytes;
        int end = cursor.pos;
        if (end < bytes.length && bytes[end] == '(' || operatorFollows()) {
            return true;
        }
        for (int i = tokenStart; i < end; i++) {
            byte b = bytes[i];
            boolean sign = b == '+' || b == '-';
            if (!TextBytes.isWordByte(b) && b != '.' && !sign && b != '*' && b != '/' && b != '^') {
                return false;
            }
            if (b == '*' || b == '/' || b == '^' || sign && i > tokenStart && !afterExponent(i)) {
                return true;
            }
        }
        return nearlyAName(tokenStart, end);
    }

    private boolean afterExponent(int i) {
        byte[] bytes = cursor.bytes;
        return (bytes[i - 1] == 'e' || bytes[i - 1] == 'E') && i - 2 >= tokenStart
                && (bytes[i - 2] >= '0' && bytes[i - 2] <= '9' || bytes[i - 2] == '.');
    }

    /** Whether {@code bytes[from, to)} holds a word that is a known name or function, or one letter away from one. */
    private boolean nearlyAName(int from, int to) {
        byte[] bytes = cursor.bytes;
        for (int i = from; i < to; i++) {
            boolean startsWord = ExpressionParser.isLetter(bytes[i])
                    && (i == from || !TextBytes.isWordByte(bytes[i - 1]) && bytes[i - 1] != '.');
            if (startsWord) {
                int end = i;
                while (end < to && TextBytes.isWordByte(bytes[end])) {
                    end++;
                }
                String word = cursor.source.text(i, end);
                String nearest = expressions().nearestName(word);
                if (nearest != null
                        && Hints.editDistance(word.toLowerCase(Locale.ROOT), nearest.toLowerCase(Locale.ROOT)) <= 1) {
                    return true;
                }
                i = end;
            }
        }
        return false;
    }

    /** A token that is no number: an error at an invisible character that starts it or follows a number, else at it. */
    private SceneException notANumber() {
        int invisible = tokenStart;
        while (invisible < cursor.pos && !(cursor.bytes[invisible] < 0 && (cursor.bytes[invisible] & 0xC0) != 0x80
                && Hints.isInvisible(cursor.source.codePointAt(invisible)))) {
            invisible++; // to the first invisible character (Hints.isInvisible), or the token's end
        }
        if (invisible == tokenStart) {
            return cursor.error(invisible, "expected a number, found " + cursor.describe(invisible), null);
        }
        if (invisible < cursor.pos) {
            try {
                FloatParser.parse(cursor.bytes, tokenStart, invisible);
                return cursor.error(invisible,
                        "expected '|' or ')' after a number, found " + cursor.describe(invisible), null);
            } catch (NumberFormatException e) {
                // no number before it: the token's message
            }
        }
        String token = cursor.source.text(tokenStart, cursor.pos);
        return cursor.error(tokenStart, "expected a number, found '" + token + "'", Hints.forNumber(token,
                group.takesWholeNumbers() ? group.of(statement) : null));
    }
}
