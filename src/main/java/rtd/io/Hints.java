package rtd.io;

import java.util.regex.Pattern;

/**
 * The {@code = help:} lines for the mistakes people really make in a scene file: a decimal
 * comma, a comment written as in another language, two statements on one line, an invisible
 * character copied from a PDF or a web page, the paper's listing pasted with its line numbers.
 *
 * <p>They are only asked for once a line has a mistake, so reading a correct file costs nothing
 * more for them.
 */
final class Hints {

    /** For a line or text that starts as a comment does in another language: {@code #}, {@code /*}. */
    static final String COMMENTS = "comments start with //";
    /** The forms of a number; "or" between them, since a comma would read as a decimal comma. */
    static final String NUMBER_FORMS = "numbers are written like 3 or -0.5 or .5 or 1. or 2e3";
    static final String LINE_NUMBERS = "it looks like the lines are numbered, as in the paper's listing: "
            + "remove the numbers at the start of each line";
    static final String SEMICOLON = "one statement per line, with nothing after it: remove the ';'";

    /** One number, with a comma where the point should be: 2,5 or -0,5 or 1,5e3. */
    private static final Pattern DECIMAL_COMMA = Pattern.compile("[+-]?[0-9]*,[0-9]+([eE][+-]?[0-9]+)?");

    private Hints() {
    }

    /** For a second statement after the first on one line. */
    static String oneStatementPerLine(String keyword) {
        return "one statement per line: start a new line before '" + keyword + "'";
    }

    /** For a token that is no number. */
    static String forNumber(String token) {
        if (token.indexOf('\u2212') >= 0) {
            return "'\u2212' is a typographic minus sign (U+2212); type the plain '-' instead";
        }
        if (DECIMAL_COMMA.matcher(token).matches()) {
            return "write decimals with a point: " + token.replace(',', '.');
        }
        if (token.indexOf(',') >= 0) {
            return "separate the numbers of a group with '|', not ','";
        }
        if (token.indexOf(';') >= 0) {
            return "separate the numbers of a group, or its properties, with '|', not ';'";
        }
        return NUMBER_FORMS;
    }

    /** For a path with a '\' that names no file: Windows separates folders so, the other systems with '/' only. */
    static String forWindowsPath(String path) {
        return "write folders with '/', as in " + path.replace('\\', '/') + ", which works on every system; "
                + "'\\' separates folders on Windows only";
    }

    /** For a token of an OBJ file that is no number: its numbers are separated by blanks, so a comma is a decimal comma. */
    static String forObjNumber(String token) {
        return DECIMAL_COMMA.matcher(token).matches() ? "write decimals with a point: " + token.replace(',', '.') : NUMBER_FORMS;
    }

    // ---- invisible characters ---------------------------------------------------------------

    /**
     * Whether a character shows as a blank or not at all, but is not one of the blanks of the
     * scene format (space, tab): U+00A0 NO-BREAK SPACE, U+200B ZERO WIDTH SPACE, U+FEFF…
     */
    static boolean isInvisible(int codePoint) {
        return codePoint > 0x7F && (Character.isSpaceChar(codePoint) || Character.getType(codePoint) == Character.FORMAT);
    }

    /** "U+00A0 NO-BREAK SPACE": how a message names an invisible character. */
    static String nameOf(int codePoint) {
        String name = Character.getName(codePoint);
        String text = String.format("U+%04X", codePoint) + (name == null ? "" : " " + name);
        return codePoint == 0xFEFF ? text + " (a byte-order mark)" : text;
    }

    /** What to do about an invisible character. */
    static String forInvisible(int codePoint) {
        String name = String.format("U+%04X", codePoint);
        if (codePoint == 0xFEFF) {
            return "a byte-order mark may stand only at the very start of a file (one gets inside when files are joined): "
                    + "delete it";
        }
        boolean looksLikeSpace = Character.isSpaceChar(codePoint) && !Character.getName(codePoint).contains("ZERO WIDTH");
        return name + (looksLikeSpace ? " looks like a space but is not one: type a plain space instead"
                : " cannot be seen but is there: delete it") + " (text copied from a PDF or a web page brings it)";
    }
}
