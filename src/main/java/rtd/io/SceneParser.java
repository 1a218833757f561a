package rtd.io;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.IntStream;
import rtd.scene.Scene;

/**
 * Reads the scene format of the paper (section 4.1, Listing A.1), as Part II ("The scene
 * file") extends it, from a file's bytes.
 *
 * <p>One statement a line: {@code keyword:(group):(group)…}, the statements being those of the
 * {@link Grammar}. {@code //} starts a comment; blank lines, spaces and tabs around any token,
 * Windows and old Mac line ends (CR LF, a CR alone) and a UTF-8 byte-order mark are all fine.
 * Every mistake is reported with its line and column, up to {@value #MAX_ERRORS}, so that one run
 * shows them all.
 *
 * <p>A large file is cut at line breaks into parts ({@link FileCuts}) that
 * {@link StatementReader}s read in parallel; the parts are joined in file order
 * ({@link PartJoin}), so the scene and the messages are the same as from reading the file in one
 * go. Joining is also where what only the whole file can tell is checked: one camera, one
 * {@code ambient}, one material per name; and where the objects that name a material, which may
 * be defined further down, are built.
 */
final class SceneParser {

    /** After this many errors reading stops; more would only scroll the first ones away. */
    static final int MAX_ERRORS = 20;
    /** The size of the parts a large file is cut into: big enough to be worth a task. */
    private static final int PART_SIZE = 4 << 20;

    /** Fewer bytes than any line that makes an object, {@code sphere:(0|0|0):(1):(0|0|0)} and its line break. */
    private static final int SHORTEST_OBJECT = 24;

    private SceneParser() {
    }

    /**
     * Reads a scene, or throws every mistake found in it; what is no mistake but likely a slip
     * goes to {@code warnings} (null: dropped), in file order.
     */
    static Scene parse(SourceText source, List<SceneError> warnings) throws SceneException {
        return parse(source, PART_SIZE, warnings);
    }

    /** As {@link #parse(SourceText, List)} without the warnings, cutting the file into parts of about {@code partSize} bytes. */
    static Scene parse(SourceText source, int partSize) throws SceneException {
        return parse(source, partSize, null);
    }

    /** As {@link #parse(SourceText, List)}, cutting the file into parts of about {@code partSize} bytes. */
    static Scene parse(SourceText source, int partSize, List<SceneError> warnings) throws SceneException {
        byte[] bytes = source.bytes();
        int start = ByteClasses.startsWithByteOrderMark(bytes) ? 3 : 0;
        int[] cuts = FileCuts.cuts(bytes, start, partSize);
        TextScan[] scans = FileCuts.scan(bytes, cuts);
        for (TextScan scan : scans) {
            if (scan.badByte() >= 0) {
                throw new SceneException(List.of(NotText.error(source, start, scan.badByte())), false);
            }
        }
        int[] firstLines = FileCuts.firstLines(scans);
        // The first part, alone and first: it holds the file's first lines, most often its
        // comments, ambient and camera. Read later, they would meet a reader that the JIT has
        // compiled for sphere lines only, and it would throw that away and compile it again.
        List<ScenePart> parts = new ArrayList<>();
        parts.add(readPart(source, cuts, firstLines, 0));
        if (!FileCuts.onePart(cuts)) {
            parts.addAll(IntStream.range(1, cuts.length - 1).parallel().mapToObj(k -> readPart(source, cuts, firstLines, k)).toList());
        }
        if (aCommentSpansACut(parts)) {
            // A part that starts inside a /* comment took its lines for statements. Such a file
            // has a mistake (the /*), so its speed matters less than its messages being those
            // of one part: it is read again in one go.
            parts = List.of(readPart(source, new int[] {start, bytes.length}, new int[] {1, firstLines[cuts.length - 1]}, 0));
        }
        return PartJoin.join(source, parts, warnings);
    }

    private static boolean aCommentSpansACut(List<ScenePart> parts) {
        for (int k = 0; k < parts.size() - 1; k++) {
            if (parts.get(k).endsInBlockComment) {
                return true;
            }
        }
        return false;
    }

    private static ScenePart readPart(SourceText source, int[] cuts, int[] firstLines, int k) {
        // Most lines of a large file make one object, so the part's list is made that long at
        // once (growing it line by line would copy it a dozen times); a blank line makes none,
        // and the shortest line that makes one is longer than SHORTEST_OBJECT bytes.
        int lines = firstLines[k + 1] - firstLines[k] + 1;
        ScenePart part = new ScenePart(Math.min(lines, (cuts[k + 1] - cuts[k]) / SHORTEST_OBJECT + 1));
        new StatementReader(source, cuts[k], cuts[k + 1], firstLines[k], part).readAll();
        return part;
    }
}
