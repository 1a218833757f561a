package rtd.io;

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
            Window window = Window.around(sourceLine, column);
            text.append(' ').append(number).append(" | ").append(window.shown()).append('\n');
            text.append(gutter).append("| ").append(window.caretPadding()).append("^\n");
        }
        if (help != null) {
            text.append(gutter).append("= help: ").append(help).append('\n');
        }
        return text.toString();
    }

    /**
     * The part of a long line shown: at most {@value #WIDTH} characters around the column, an ellipsis for
     * each end cut off.
     *
     * @param shown        the text to print
     * @param caretPadding what goes before the caret: spaces, and the line's tabs so that it lines up
     */
    private record Window(String shown, String caretPadding) {

        static final int WIDTH = 100;
        /** How many characters of a long line are shown before the column. */
        static final int BEFORE = 40;

        static Window around(String line, int column) {
            int length = line.codePointCount(0, line.length());
            int start = length <= WIDTH ? 0 : Math.max(0, Math.min(column - 1 - BEFORE, length - WIDTH));
            int end = Math.min(length, start + WIDTH);
            int from = line.offsetByCodePoints(0, start);
            String part = line.substring(from, line.offsetByCodePoints(from, end - start));
            String before = start > 0 ? "…" : "";
            String after = end < length ? "…" : "";
            return new Window(before + part + after, " ".repeat(before.length()) + padding(part, column - 1 - start));
        }

        /** {@code columns} columns of {@code part}: its tabs kept, everything else a space. */
        private static String padding(String part, int columns) {
            StringBuilder padding = new StringBuilder();
            int offset = 0;
            for (int i = 0; i < columns && offset < part.length(); i++) {
                int codePoint = part.codePointAt(offset);
                padding.append(codePoint == '\t' ? '\t' : ' ');
                offset += Character.charCount(codePoint);
            }
            return padding.append(" ".repeat(Math.max(0, columns - padding.length()))).toString();
        }
    }
}
