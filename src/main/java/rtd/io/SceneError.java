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
        StringBuilder text = new StringBuilder();
        text.append(file).append(':').append(line).append(':').append(column)
                .append(": error: ").append(message).append('\n');
        String number = String.valueOf(line);
        String gutter = " ".repeat(number.length() + 2);
        if (sourceLine != null) {
            text.append(' ').append(number).append(" | ").append(sourceLine).append('\n');
            text.append(gutter).append("| ").append(caretPadding()).append("^\n");
        }
        if (help != null) {
            text.append(gutter).append("= help: ").append(help).append('\n');
        }
        return text.toString();
    }

    /** Spaces up to the column, keeping the line's tabs so that the caret lines up. */
    private String caretPadding() {
        StringBuilder padding = new StringBuilder();
        int offset = 0;
        for (int i = 1; i < column && offset < sourceLine.length(); i++) {
            int codePoint = sourceLine.codePointAt(offset);
            padding.append(codePoint == '\t' ? '\t' : ' ');
            offset += Character.charCount(codePoint);
        }
        return padding.append(" ".repeat(Math.max(0, column - 1 - padding.length()))).toString();
    }
}
