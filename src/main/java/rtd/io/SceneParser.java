package rtd.io;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import rtd.geometry.IGeometry;
import rtd.image.Color;
import rtd.scene.Scene;

/**
 * Reads a scene file (paper, section 4.1, Listing A.1; Part II, "The scene file"): one statement of the
 * {@link Grammar} a line, {@code //} comments, any blanks, line ends and a byte-order mark. Text that is not
 * UTF-8 is refused at its first bad byte; every mistake is reported with line and column, in file order, up
 * to {@value #MAX_ERRORS}.
 *
 * After the {@link StatementReader} has read every line, it checks what only the whole file can tell (one
 * camera, one {@code ambient}, one material per name), builds the objects that name a material defined
 * further down, and gives the warnings of slips that are no mistakes.
 */
final class SceneParser {

    /** After this many errors reading stops; more would only scroll the first ones away. */
    static final int MAX_ERRORS = 20;
    /** Fewer bytes than any line that makes an object, {@code sphere:(0|0|0):(1):(0|0|0)} and its line break. */
    private static final int SHORTEST_OBJECT = 24;
    private static final String CAMERA_EXAMPLE = "orthographic_camera:(0|0|20):(0|0|-1):(50)";

    private SceneParser() {
    }

    /**
     * Reads a scene at the clock and with the named values of {@code names} (Part III), or throws its mistakes;
     * likely slips go to {@code warnings} (null: dropped), in file order.
     */
    static Scene parse(SourceText source, Names names, List<SceneError> warnings) throws SceneException {
        byte[] bytes = source.bytes();
        int start = TextBytes.startsWithByteOrderMark(bytes) ? 3 : 0;
        int lines = 1;
        boolean plain = true;
        for (int i = start; i < bytes.length; i++) {
            if (bytes[i] <= '\r') { // one test for the rare bytes: line breaks, control characters, every non-ASCII byte
                lines += bytes[i] == '\n' || bytes[i] == '\r' && TextBytes.endsLine(bytes, i) ? 1 : 0;
                plain &= bytes[i] > 0;
            }
        }
        int bad = plain ? -1 : TextBytes.firstBadByte(bytes, start, bytes.length);
        if (bad >= 0) {
            throw new SceneException(List.of(TextBytes.error(source, start, bad)), false);
        }
        // Most lines of a large file make one object, so the list is made that long at once: grown
        // line by line, its large arrays would go to the old generation, and stay there long.
        SceneContents contents = new SceneContents(Math.min(lines, (bytes.length - start) / SHORTEST_OBJECT + 1));
        new StatementReader(source, start, contents, names).readAll();
        return join(source, contents, warnings);
    }

    /** The scene the contents make, or every mistake in them, ordered by place. */
    private static Scene join(SourceText source, SceneContents contents, List<SceneError> warnings) throws SceneException {
        List<SceneContents.Found> errors = contents.errors;
        addLineNumbers(contents, errors);
        var ambients = contents.ambients;
        var cameras = contents.cameras;
        onlyOne(ambients, "a second 'ambient': a scene has one background colour", "the first 'ambient'", errors);
        onlyOne(cameras, "a second camera: a scene has one", "the first camera", errors);
        DefinedNames names = new DefinedNames(contents, errors);
        Set<String> named = new HashSet<>(contents.namedAtOnce);
        List<IGeometry> objects = contents.allObjects(names, named);
        if (errors.isEmpty() && contents.statementCount == 0) {
            errors.add(atStart(source, "the scene is empty: it has no statements, only blanks and comments",
                    "a scene needs at least a camera, such as " + CAMERA_EXAMPLE).found());
        } else if (errors.isEmpty() && cameras.isEmpty()) {
            errors.add(atStart(source, "the scene has no camera", "add a line such as " + CAMERA_EXAMPLE).found());
        }
        if (!errors.isEmpty()) {
            errors.sort(Comparator.comparingInt(SceneContents.Found::line).thenComparingInt(SceneContents.Found::column));
            List<SceneError> shown = errors.subList(0, Math.min(MAX_ERRORS, errors.size())).stream()
                    .map(SceneContents.Found::error).toList();
            throw new SceneException(shown, errors.size() > MAX_ERRORS);
        }
        if (warnings != null) {
            boolean lit = !contents.lights.isEmpty();
            warnings.addAll(names.materialWarnings(named, lit));
            warnings.addAll(names.unused(named));
            if (lit) {
                List<SceneError> acne = new ArrayList<>(contents.litWarnings);
                acne.sort(Comparator.comparingInt(SceneError::line));
                warnings.addAll(acne.subList(0, Math.min(MAX_ERRORS, acne.size())));
            }
        }
        Color ambient = ambients.isEmpty() ? Color.BLACK : ambients.get(0).value();
        return new Scene(ambient, cameras.get(0).value(), objects, contents.lights);
    }

    /** An error at each of {@code found} after the first, which {@code first} names in the help. */
    private static void onlyOne(List<? extends SceneContents.Located<?>> found, String second, String first,
            List<SceneContents.Found> errors) {
        for (var located : found.subList(Math.min(1, found.size()), found.size())) {
            errors.add(located.place().saying(second, first + " is at line " + found.get(0).place().line()).found());
        }
    }

    /** The lines that start with a line number, as one mistake at the first of them. */
    private static void addLineNumbers(SceneContents contents, List<SceneContents.Found> errors) {
        SceneError first = contents.firstLineNumber;
        int count = contents.lineNumbers;
        if (first != null) {
            String more = count == 1 ? "" : count == 2 ? ", as does 1 more line" : ", as do " + (count - 1) + " more lines";
            errors.add(first.saying(first.message() + more, first.help()).found());
        }
    }

    private static SceneError atStart(SourceText source, String message, String help) {
        int start = TextBytes.startsWithByteOrderMark(source.bytes()) ? 3 : 0;
        return source.errorAt(1, start, start, message, help);
    }
}
