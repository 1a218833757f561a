package rtd.io;

import java.util.stream.Collectors;

/**
 * One mistake in a scene file, located the way a compiler locates it.
 *
 * @param file       the file's name as the user gave it
 * @param line       the line, from 1
 * @param column     the column, from 1, counted in characters
 * @param message    what was expected and what was found
 * @param sourceLine the text of the offending line, shown with a caret under the column; null
 *                   when there is no line to show (a file that is not text)
 * @param help       a hint such as "did you mean 'sphere'?", or null
 */
public record SceneError(String file, int line, int column, String message, String sourceLine, String help) {

    /** This error as one of a scene's, ordered by its place. */
    SceneContents.Found found() {
        return new SceneContents.Found(line, column, this);
    }

    /** Another message and help at the same place. */
    SceneError saying(String message, String help) {
        return new SceneError(file, line, column, message, sourceLine, help);
    }

    /**
     * The error as a compiler prints it:
     * <pre>
     * scene.txt:3:7: error: expected ':' after 'sphere', found '('
     *     3 | sphere(3|8|-1):(2):(0|127|255)
     *       |       ^
     *       = help: ...
     * </pre>
     */
    public String format() {
        return format("error");
    }

    /** As {@link #format()}, for a warning: the same place, excerpt and help, as {@code warning:}. */
    public String formatAsWarning() {
        return format("warning");
    }

    private String format(String kind) {
        StringBuilder text = new StringBuilder();
        text.append(file).append(':').append(line).append(':').append(column)
                .append(": ").append(kind).append(": ").append(message).append('\n');
        String number = String.valueOf(line);
        String gutter = " ".repeat(number.length() + 2);
        if (sourceLine != null) {
            excerpt(text.append(' ').append(number).append(" | "), gutter);
        }
        if (help != null) {
            text.append(gutter).append("= help: ").append(help).append('\n');
        }
        return text.toString();
    }

    /** At most {@value #WIDTH} characters of a long line shown, a caret under the column. */
    private static final int WIDTH = 100;
    /** How many characters of a long line are shown before the column. */
    private static final int BEFORE = 40;

    /**
     * The part of the line shown around the column, an ellipsis for each end cut off, and the caret under it:
     * what goes before the caret is spaces, and the line's tabs so that it lines up.
     */
    private void excerpt(StringBuilder text, String gutter) {
        int length = sourceLine.codePointCount(0, sourceLine.length());
        int start = length <= WIDTH ? 0 : Math.max(0, Math.min(column - 1 - BEFORE, length - WIDTH));
        int end = Math.min(length, start + WIDTH);
        int from = sourceLine.offsetByCodePoints(0, start);
        String part = sourceLine.substring(from, sourceLine.offsetByCodePoints(from, end - start));
        String before = start > 0 ? "…" : "";
        text.append(before).append(part).append(end < length ? "…" : "").append('\n');
        int columns = column - 1 - start;
        String tabs = part.codePoints().limit(Math.max(0, columns)).mapToObj(c -> c == '\t' ? "\t" : " ")
                .collect(Collectors.joining());
        text.append(gutter).append("| ").append(" ".repeat(before.length())).append(tabs)
                .append(" ".repeat(Math.max(0, columns - tabs.length()))).append("^\n");
    }
}
