package rtd.explain;

/**
 * The text of an explanation, line by line, indented by depth: the steps of a pixel, and the
 * tree of its secondary rays.
 */
final class Text {

    private final StringBuilder text = new StringBuilder();
    private int depth;

    /** Adds one line at the current depth. */
    Text line(String line) {
        text.append("   ".repeat(depth)).append(line).append('\n');
        return this;
    }

    /** Adds a heading line one step less deep than the lines under it (a hanging indent). */
    Text hanging(String line) {
        text.append("   ".repeat(Math.max(0, depth - 1))).append(line).append('\n');
        return this;
    }

    /** Adds an empty line. */
    Text blank() {
        text.append('\n');
        return this;
    }

    /** Lines from now on go one step deeper. */
    Text in() {
        depth++;
        return this;
    }

    /** Lines from now on go one step shallower. */
    Text out() {
        depth--;
        return this;
    }

    @Override
    public String toString() {
        return text.toString();
    }
}
