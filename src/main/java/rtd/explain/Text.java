package rtd.explain;

/**
 * The text of an explanation, line by line, indented by depth: the steps of a pixel, and the tree of its secondary
 * rays.
 */
final class Text {

    private final StringBuilder text = new StringBuilder();
    private int depth;

    Text line(String line) {
        text.append("   ".repeat(depth)).append(line).append('\n');
        return this;
    }

    /** Adds a heading line one step less deep than the lines under it (a hanging indent). */
    Text hanging(String line) {
        text.append("   ".repeat(Math.max(0, depth - 1))).append(line).append('\n');
        return this;
    }

    Text blank() {
        text.append('\n');
        return this;
    }

    Text in() {
        depth++;
        return this;
    }

    Text out() {
        depth--;
        return this;
    }

    @Override
    public String toString() {
        return text.toString();
    }
}
