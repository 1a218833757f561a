package rtd.io;

import java.util.stream.Collectors;

/**
 * One mistake in a scene file, located the way a compiler locates it, and printed so:
 * <pre>
 * scene.txt:3:7: error: expected ':' after 'sphere', found '('
 *     3 | sphere(3|8|-1):(2):(0|127|255)
 *       |       ^
 *       = help: ...
 * </pre>
 Line and column count from 1, the column in characters; {@code sourceLine} is null for a file that is not text,
 * {@code help} may be null. A line longer than {@value #WIDTH} characters is shown around the column.
 */
public record SceneError(String file, int line, int column, String message, String sourceLine, String help) {

    private static final int WIDTH = 100;
    /** How many characters of a long line are shown before the column. */
    private static final int BEFORE = 40;

    SceneContents.Found found() {
        return new SceneContents.Found(line, column, this);
    }

    SceneError saying(String message, String help) {
        return new SceneError(file, line, column, message, sourceLine, help);
    }

    public String format() {
        return format("error");
    }

    public String formatAsWarning() {
        return format("warning");
    }

    private String format(String kind) {
        StringBuilder text = new StringBuilder(file + ":" + line + ":" + column + ": " + kind + ": " + message + "\n");
        String gutter = " ".repeat(String.valueOf(line).length() + 2);
        if (sourceLine != null) {
            int length = sourceLine.codePointCount(0, sourceLine.length());
            int start = length <= WIDTH ? 0 : Math.max(0, Math.min(column - 1 - BEFORE, length - WIDTH));
            int end = Math.min(length, start + WIDTH);
            int from = sourceLine.offsetByCodePoints(0, start);
            String part = sourceLine.substring(from, sourceLine.offsetByCodePoints(from, end - start));
            String before = start > 0 ? "…" : "";
            text.append(' ').append(line).append(" | ").append(before).append(part).append(end < length ? "…" : "")
                    .append('\n');
            // Under the line: spaces, and its tabs, so that the caret lines up.
            int columns = column - 1 - start;
            String tabs = part.codePoints().limit(Math.max(0, columns)).mapToObj(c -> c == '\t' ? "\t" : " ")
                    .collect(Collectors.joining());
            text.append(gutter).append("| ").append(" ".repeat(before.length())).append(tabs)
                    .append(" ".repeat(Math.max(0, columns - tabs.length()))).append("^\n");
        }
        if (help != null) {
            text.append(gutter).append("= help: ").append(help).append('\n');
        }
        return text.toString();
    }
}
