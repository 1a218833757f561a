package rtd.io;

import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The three statements of the scene format (paper, section 4.1 and Listing A.1): their
 * keywords and the groups of numbers each takes.
 */
enum Statement {
    AMBIENT("ambient", new Group("colour", "R|G|B")),
    ORTHOGRAPHIC_CAMERA("orthographic_camera",
            new Group("position", "x|y|z"), new Group("view direction", "x|y|z"), new Group("zoom", "zoom")),
    SPHERE("sphere", new Group("centre", "x|y|z"), new Group("radius", "r"), new Group("colour", "R|G|B"));

    /**
     * One group of a statement: what it means, the names of its numbers (such as
     * {@code x|y|z}), and how many numbers it holds.
     */
    record Group(String meaning, String shape, int size) {

        Group(String meaning, String shape) {
            this(meaning, shape, shape.split("\\|").length);
        }
    }

    /** Every statement; {@code values()} would copy the array for each line read. */
    private static final Statement[] ALL = values();

    final String keyword;
    final List<Group> groups;
    private final byte[] keywordBytes;

    Statement(String keyword, Group... groups) {
        this.keyword = keyword;
        this.groups = List.of(groups);
        this.keywordBytes = keyword.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
    }

    /** The statement whose keyword is {@code bytes[start, end)}, or null. */
    static Statement find(byte[] bytes, int start, int end) {
        for (Statement statement : ALL) {
            if (Arrays.equals(statement.keywordBytes, 0, statement.keywordBytes.length, bytes, start, end)) {
                return statement;
            }
        }
        return null;
    }

    /** The statement's full form, such as {@code sphere:(x|y|z):(r):(R|G|B)}. */
    String usage() {
        return keyword + groups.stream().map(g -> ":(" + g.shape() + ")").collect(Collectors.joining());
    }

    /** All keywords, for messages: "ambient, orthographic_camera or sphere". */
    static String keywordList() {
        return "'ambient', 'orthographic_camera' or 'sphere'";
    }
}
