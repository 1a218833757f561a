package rtd.io;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Reads one expression of a scene file into an {@link Expression} tree by recursive descent, one method per level
 * of the grammar (Part III, "Expressions, named values and the clock"):
 *
 * <pre>
 * sum     = product { ("+" | "-") product }
 * product = unary { ("*" | "/") unary }
 * unary   = ("-" | "+") unary | power
 * power   = atom [ "^" unary ]                  (right-associative: 2^3^2 = 2^9; -2^2 = -4)
 * atom    = number | name | function "(" sum { "," sum } ")" | "(" sum ")"
 * </pre>
 *
 * It stops before the first byte that cannot go on the expression (a {@code |} or the group's {@code )}).
 */
final class ExpressionParser {

    /** Deeper nesting than this is a mistake, not a scene: it would overflow the reader's stack. */
    static final int MAX_DEPTH = 100;
    /** More operators than this in one expression are a mistake too: its tree would be as deep to evaluate. */
    static final int MAX_OPERATORS = 1000;
    private static final String OPERATORS = "an operator (+ - * / ^)";

    private final LineCursor cursor;
    private final Names names;
    private int depth;
    private int operators;

    ExpressionParser(LineCursor cursor, Names names) {
        this.cursor = cursor;
        this.names = names;
    }

    Expression read() throws SceneException {
        depth = 0;
        operators = 0;
        Expression expression = sum();
        cursor.skipBlanks();
        if (isDigitOrPoint(next()) || isLetter(next()) || cursor.at('(')) { // "2 x", "2(3)": a product needs its '*'
            int end = cursor.pos;
            while (end > 0 && TextBytes.isSpace(cursor.bytes[end - 1])) {
                end--;
            }
            throw cursor.error(cursor.pos, "expected " + OPERATORS + ", '|' or ')' after " + cursor.source.text(
                    expression.start(), end) + ", found " + cursor.describe(cursor.pos),
                    "a product is written with '*', such as 2*x");
        }
        return expression;
    }

    private Expression sum() throws SceneException {
        Expression left = product();
        for (cursor.skipBlanks(); cursor.at('+') || cursor.at('-'); cursor.skipBlanks()) {
            int at = operator();
            left = new Expression.Operation((char) cursor.bytes[at], left, product(), at);
        }
        return left;
    }

    /** A '/' that starts a {@code //} comment ends the expression. */
    private Expression product() throws SceneException {
        Expression left = unary();
        for (cursor.skipBlanks(); cursor.at('*') || cursor.at('/') && !cursor.atEndOfStatement(); cursor.skipBlanks()) {
            int at = operator();
            left = new Expression.Operation((char) cursor.bytes[at], left, unary(), at);
        }
        return left;
    }

    /** A minus sign binds looser than {@code ^}: {@code -2^2} is {@code -(2^2)}. */
    private Expression unary() throws SceneException {
        cursor.skipBlanks();
        if (++depth > MAX_DEPTH) {
            throw cursor.error(cursor.pos, "the expression is nested too deeply: more than " + MAX_DEPTH + " levels",
                    "split it with let:(name):(expression) lines");
        }
        try {
            if (cursor.at('-')) {
                int at = operator();
                return new Expression.Negation(unary(), at);
            }
            if (cursor.at('+')) {
                cursor.pos++;
                return unary();
            }
            return power();
        } finally {
            depth--;
        }
    }

    private Expression power() throws SceneException {
        Expression base = atom();
        cursor.skipBlanks();
        if (!cursor.at('^')) {
            return base;
        }
        int at = operator();
        return new Expression.Operation('^', base, unary(), at);
    }

    private Expression atom() throws SceneException {
        cursor.skipBlanks();
        if (cursor.at('(')) {
            int open = cursor.pos++;
            Expression inner = sum();
            expectClosing(open, "the '('");
            return inner;
        }
        if (isDigitOrPoint(next())) {
            return number();
        }
        if (isLetter(next())) {
            return nameOrCall();
        }
        boolean atGroupEnd = cursor.at('|') || cursor.at(')') || cursor.atEndOfStatement();
        throw cursor.error(cursor.pos, "expected a number, a name or '(' in an expression, found "
                + cursor.describe(cursor.pos), atGroupEnd ? "an operator needs a number on either side" : null);
    }

    private Expression number() throws SceneException {
        int start = cursor.pos;
        while (isDigitOrPoint(next())) {
            cursor.pos++;
        }
        int beforeExponent = cursor.pos;
        if (cursor.at('e') || cursor.at('E')) {
            cursor.pos++;
            if (cursor.at('+') || cursor.at('-')) {
                cursor.pos++;
            }
            int digits = cursor.pos;
            while (next() >= '0' && next() <= '9') {
                cursor.pos++;
            }
            if (cursor.pos == digits) {
                cursor.pos = beforeExponent; // "2e" is no exponent: the 'e' is left for the next token
            }
        }
        String text = new String(cursor.bytes, start, cursor.pos - start, StandardCharsets.US_ASCII);
        try {
            return new Expression.Number(Double.parseDouble(text), start);
        } catch (NumberFormatException e) { // "1.2.3", "."
            throw cursor.error(start, "expected a number, found '" + text + "'", Hints.NUMBER_FORMS);
        }
    }

    private Expression nameOrCall() throws SceneException {
        int start = cursor.pos;
        int end = cursor.afterWord(start);
        String word = cursor.source.text(start, end);
        cursor.pos = cursor.afterSpaces(end);
        Expression.Function function = Expression.Function.named(word);
        if (cursor.at('(')) {
            if (function == null) {
                throw unknownFunction(word, start);
            }
            return call(function, start);
        }
        cursor.pos = end;
        if (function != null) {
            throw cursor.error(start, "'" + word + "' is a function, and it needs its argument in parentheses",
                    "write it as " + function.usage());
        }
        Expression name = names.lookUp(word, start);
        if (name == null) {
            throw unknownName(word, start);
        }
        names.clockUsed |= name.usesClock();
        return name;
    }

    private Expression call(Expression.Function function, int start) throws SceneException {
        int open = cursor.pos++;
        List<Expression> arguments = new ArrayList<>(List.of(sum()));
        for (cursor.skipBlanks(); cursor.at(','); cursor.skipBlanks()) {
            cursor.pos++;
            arguments.add(sum());
        }
        expectClosing(open, "'" + function.name() + "('");
        if (arguments.size() != function.arity()) {
            String takes = function.arity() == 1 ? "1 argument" : function.arity() + " arguments";
            throw cursor.error(start, "'" + function.name() + "' takes " + takes + ", found " + arguments.size(),
                    "write it as " + function.usage());
        }
        return new Expression.Call(function, arguments, start);
    }

    /** The ')' that closes the '(' at {@code open}, which {@code what} names in the message. */
    private void expectClosing(int open, String what) throws SceneException {
        cursor.skipBlanks();
        if (cursor.at(')')) {
            cursor.pos++;
            return;
        }
        String found = cursor.describe(cursor.pos);
        throw cursor.error(cursor.pos, "expected " + OPERATORS + " or ')' to close " + what + " at column "
                + cursor.source.column(cursor.lineStart, open) + ", found " + found,
                cursor.at(',') ? "',' separates the arguments of a function, such as max(a, b)"
                        : "every '(' in an expression needs its ')'");
    }

    private SceneException unknownFunction(String word, int start) {
        String nearest = near(word, Hints.nearest(word, Expression.Function.NAMES));
        String product = names.lookUp(word, start) == null ? ""
                : "; a product is written with '*', such as " + word + "*(…)";
        String functions = "the functions are " + String.join(", ", Expression.Function.NAMES) + product;
        return cursor.error(start, "unknown function '" + word + "'", Hints.didYouMean(nearest, functions));
    }

    private SceneException unknownName(String word, int start) {
        if (names.isBroken(word)) { // its let's mistake is reported there: this statement is only left out
            return new SceneException(cursor.error(start, "", null).place, List.of());
        }
        return cursor.error(start, "unknown name '" + word + "'", Hints.didYouMean(nearestName(word),
                "define it above this line with let:(" + word + "):(1), or use clock or pi"));
    }

    String nearestName(String word) {
        List<String> candidates = new ArrayList<>(names.known());
        candidates.addAll(Expression.Function.NAMES);
        return near(word, Hints.nearest(word, candidates));
    }

    /** {@code nearest} if it is a slip of {@code word}: an edit for every three letters, at least one; else null. */
    private static String near(String word, String nearest) {
        return nearest != null && Hints.editDistance(word.toLowerCase(Locale.ROOT), nearest.toLowerCase(Locale.ROOT))
                <= Math.max(1, word.length() / 3) ? nearest : null;
    }

    /** Passes the operator at the cursor and answers where it stands. */
    private int operator() throws SceneException {
        if (++operators > MAX_OPERATORS) {
            throw cursor.error(cursor.pos, "the expression is too long: more than " + MAX_OPERATORS + " operators",
                    "split it with let:(name):(expression) lines");
        }
        return cursor.pos++;
    }

    /** The byte at the cursor, or 0 (which starts nothing) at the end of the file. */
    private byte next() {
        return cursor.pos < cursor.bytes.length ? cursor.bytes[cursor.pos] : 0;
    }

    static boolean isLetter(byte b) {
        return (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z');
    }

    private static boolean isDigitOrPoint(byte b) {
        return (b >= '0' && b <= '9') || b == '.';
    }
}
