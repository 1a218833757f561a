package rtd.io;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.IntStream;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * Reads the scene format of the paper (section 4.1, Listing A.1), as Part II of the spec extends
 * it, from a file's bytes.
 *
 * <p>One statement a line: {@code keyword:(group):(group)…}, the statements being those of the
 * {@link Grammar}. {@code //} starts a comment; blank lines, spaces and tabs around any token,
 * Windows and old Mac line ends (CR LF, a CR alone) and a UTF-8 byte-order mark are all fine.
 * Every mistake is reported with its line and column, up to {@value #MAX_ERRORS}, so that one run
 * shows them all.
 *
 * <p>A large file is cut at line breaks into parts that {@link StatementReader}s read in
 * parallel; the parts are joined in file order, so the scene and the messages are the same
 * as from reading the file in one go. Joining is also where what only the whole file can tell
 * is checked: one camera, one {@code ambient}, one material per name; and where the objects that
 * name a material, which may be defined further down, are built.
 */
final class SceneParser {

    /** After this many errors reading stops; more would only scroll the first ones away. */
    static final int MAX_ERRORS = 20;
    /** The size of the parts a large file is cut into: big enough to be worth a task. */
    private static final int PART_SIZE = 4 << 20;

    /** Fewer bytes than any line that makes an object, {@code sphere:(0|0|0):(1):(0|0|0)} and its line break. */
    private static final int SHORTEST_OBJECT = 24;

    private static final String CAMERA_EXAMPLE = "orthographic_camera:(0|0|20):(0|0|-1):(50)";

    private SceneParser() {
    }

    /** Reads a scene, or throws every mistake found in it. */
    static Scene parse(SourceText source) throws SceneException {
        return parse(source, PART_SIZE);
    }

    /** As {@link #parse(SourceText)}, cutting the file into parts of about {@code partSize} bytes. */
    static Scene parse(SourceText source, int partSize) throws SceneException {
        byte[] bytes = source.bytes();
        int start = hasByteOrderMark(bytes) ? 3 : 0;
        int[] cuts = cuts(bytes, start, partSize);
        TextScan[] scans = scan(bytes, cuts);
        for (TextScan scan : scans) {
            if (scan.badByte() >= 0) {
                throw new SceneException(List.of(NotText.error(source, start, scan.badByte())), false);
            }
        }
        int[] firstLines = firstLines(scans);
        // The first part, alone and first: it holds the file's first lines, most often its
        // comments, ambient and camera. Read later, they would meet a reader that the JIT has
        // compiled for sphere lines only, and it would throw that away and compile it again.
        List<ScenePart> parts = new ArrayList<>();
        parts.add(readPart(source, cuts, firstLines, 0));
        if (!onePart(cuts)) {
            parts.addAll(IntStream.range(1, cuts.length - 1).parallel().mapToObj(k -> readPart(source, cuts, firstLines, k)).toList());
        }
        if (aCommentSpansACut(parts)) {
            // A part that starts inside a /* comment took its lines for statements. Such a file
            // has a mistake (the /*), so its speed matters less than its messages being those
            // of one part: it is read again in one go.
            parts = List.of(readPart(source, new int[] {start, bytes.length}, new int[] {1, firstLines[cuts.length - 1]}, 0));
        }
        return join(source, parts);
    }

    /**
     * Whether the file is small enough to be one part. It is then read on the calling thread
     * alone, with no parallel stream: starting one would take longer than reading the file.
     */
    private static boolean onePart(int[] cuts) {
        return cuts.length == 2;
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

    // ---- cutting the file into parts ---------------------------------------------------

    /**
     * Where the parts start, each just after a line break (never between the CR and the LF of
     * one), and the end of the file last.
     */
    private static int[] cuts(byte[] bytes, int start, int partSize) {
        int count = Math.max(1, (bytes.length - start) / partSize);
        List<Integer> cuts = new ArrayList<>();
        cuts.add(start);
        for (int k = 1; k < count; k++) {
            int cut = start + (int) ((long) (bytes.length - start) * k / count);
            while (cut < bytes.length && !ByteClasses.endsLine(bytes, cut - 1)) {
                cut++;
            }
            if (cut > cuts.get(cuts.size() - 1) && cut < bytes.length) {
                cuts.add(cut);
            }
        }
        cuts.add(bytes.length);
        int[] array = new int[cuts.size()];
        for (int k = 0; k < array.length; k++) {
            array[k] = cuts.get(k);
        }
        return array;
    }

    /**
     * Each part's {@link TextScan}, in parallel if there are several. Only a part that is text
     * is read, so its first line number is known before it is.
     */
    private static TextScan[] scan(byte[] bytes, int[] cuts) {
        if (onePart(cuts)) {
            return new TextScan[] {TextScan.of(bytes, cuts[0], cuts[1])};
        }
        return IntStream.range(0, cuts.length - 1).parallel()
                .mapToObj(k -> TextScan.of(bytes, cuts[k], cuts[k + 1]))
                .toArray(TextScan[]::new);
    }

    /** The number of the first line of each part, and last the number a line after the last part would have. */
    private static int[] firstLines(TextScan[] scans) {
        int[] firstLines = new int[scans.length + 1];
        firstLines[0] = 1;
        for (int k = 1; k <= scans.length; k++) {
            firstLines[k] = firstLines[k - 1] + scans[k - 1].lineBreaks();
        }
        return firstLines;
    }

    // ---- joining the parts ----------------------------------------------------------------

    private static Scene join(SourceText source, List<ScenePart> parts) throws SceneException {
        List<ScenePart.Found> errors = new ArrayList<>();
        List<ScenePart.Located<Color>> ambients = new ArrayList<>();
        List<ScenePart.Located<ICamera>> cameras = new ArrayList<>();
        List<ScenePart.Located<ScenePart.Named>> definitions = new ArrayList<>();
        Set<String> broken = new HashSet<>();
        List<Light> lights = new ArrayList<>();
        int statements = 0;
        addLineNumbers(parts, errors);
        for (ScenePart part : parts) {
            lights.addAll(part.lights);
            errors.addAll(part.errors);
            ambients.addAll(part.ambients);
            cameras.addAll(part.cameras);
            definitions.addAll(part.materials);
            broken.addAll(part.brokenDefinitions);
            statements += part.statementCount;
        }
        for (ScenePart.Located<Color> second : ambients.subList(Math.min(1, ambients.size()), ambients.size())) {
            errors.add(found(again(second.place(), "a second 'ambient': a scene has one background colour",
                    "the first 'ambient' is at line " + ambients.get(0).place().line())));
        }
        for (ScenePart.Located<ICamera> second : cameras.subList(Math.min(1, cameras.size()), cameras.size())) {
            errors.add(found(again(second.place(), "a second camera: a scene has one",
                    "the first camera is at line " + cameras.get(0).place().line())));
        }
        Map<String, Material> materials = materials(definitions, errors);
        List<IGeometry> objects = objects(parts, materials, broken, errors);
        if (errors.isEmpty() && statements == 0) {
            errors.add(found(atStart(source, "the scene is empty: it has no statements, only blanks and comments",
                    "a scene needs at least a camera, such as " + CAMERA_EXAMPLE)));
        } else if (errors.isEmpty() && cameras.isEmpty()) {
            errors.add(found(atStart(source, "the scene has no camera", "add a line such as " + CAMERA_EXAMPLE)));
        }
        if (!errors.isEmpty()) {
            errors.sort(Comparator.comparingInt(ScenePart.Found::line).thenComparingInt(ScenePart.Found::column));
            List<SceneError> shown = errors.subList(0, Math.min(MAX_ERRORS, errors.size())).stream()
                    .map(ScenePart.Found::error).toList();
            throw new SceneException(shown, errors.size() > MAX_ERRORS);
        }
        Color ambient = ambients.isEmpty() ? Color.BLACK : ambients.get(0).value();
        return new Scene(ambient, cameras.get(0).value(), objects, lights);
    }

    /** The lines that start with a line number, as one mistake at the first of them. */
    private static void addLineNumbers(List<ScenePart> parts, List<ScenePart.Found> errors) {
        SceneError first = null;
        int count = 0;
        for (ScenePart part : parts) {
            first = first != null ? first : part.firstLineNumber;
            count += part.lineNumbers;
        }
        if (first != null) {
            String more = count == 1 ? "" : count == 2 ? ", as does 1 more line" : ", as do " + (count - 1) + " more lines";
            errors.add(found(again(first, first.message() + more, first.help())));
        }
    }

    /** The materials by name; a name defined again is an error at the second definition. */
    private static Map<String, Material> materials(List<ScenePart.Located<ScenePart.Named>> definitions,
            List<ScenePart.Found> errors) {
        Map<String, ScenePart.Located<ScenePart.Named>> first = new HashMap<>();
        Map<String, Material> materials = new HashMap<>();
        for (ScenePart.Located<ScenePart.Named> definition : definitions) {
            String name = definition.value().name();
            ScenePart.Located<ScenePart.Named> earlier = first.putIfAbsent(name, definition);
            if (earlier == null) {
                materials.put(name, definition.value().material());
            } else {
                errors.add(found(again(definition.place(), "a second material '" + name + "': each name is defined once",
                        "the first '" + name + "' is at line " + earlier.place().line())));
            }
        }
        return materials;
    }

    /**
     * Every object in file order: those the parts built, and between them those that name a
     * material, built now that every material is known.
     */
    private static List<IGeometry> objects(List<ScenePart> parts, Map<String, Material> materials, Set<String> broken,
            List<ScenePart.Found> errors) {
        int count = 0;
        for (ScenePart part : parts) {
            count += part.objects.size() + part.pending.size(); // a pending mesh may make more
        }
        List<IGeometry> objects = new ArrayList<>(count);
        Statement.Output out = new ObjectsOutput(objects);
        for (ScenePart part : parts) {
            int next = 0;
            for (ScenePart.Pending pending : part.pending) {
                objects.addAll(part.objects.subList(next, pending.index()));
                next = pending.index();
                build(pending.values(), materials, broken, out, errors);
            }
            objects.addAll(part.objects.subList(next, part.objects.size())); // copied in bulk: early in a run, faster than one by one
        }
        return objects;
    }

    /**
     * Builds an object that names a material. An unknown name is an error at the name, unless its
     * definition has a mistake, which is reported already; the rest of the statement is still
     * checked, so that one run shows all its mistakes.
     */
    private static void build(GroupValues values, Map<String, Material> materials, Set<String> broken,
            Statement.Output out, List<ScenePart.Found> errors) {
        Statement statement = values.statement();
        int group = statement.groups().size(); // the last, optional group: the material's name
        String name = values.name(group);
        Material material = materials.get(name);
        Statement.Output target = out;
        if (material == null && !broken.contains(name)) {
            String nearest = Suggestions.nearest(name, materials.keySet());
            ScenePart.addErrors(errors, values.errorAtValue(group, 0, "unknown material '" + name + "'", nearest != null
                    ? "did you mean '" + nearest + "'?"
                    : "define it with a line such as material:(" + name + "):(diffuse=0.9)"));
        }
        if (material == null) {
            material = Material.DEFAULT;
            target = new ObjectsOutput(new ArrayList<>()); // the scene has errors: the object is only checked
        }
        values.useMaterial(material);
        try {
            statement.builder().build(values, target);
        } catch (StatementError e) {
            ScenePart.addErrors(errors, e);
        }
    }

    private static ScenePart.Found found(SceneError error) {
        return new ScenePart.Found(error.line(), error.column(), error);
    }

    private static SceneError again(SceneError place, String message, String help) {
        return new SceneError(place.file(), place.line(), place.column(), message, place.sourceLine(), help);
    }

    private static SceneError atStart(SourceText source, String message, String help) {
        int start = hasByteOrderMark(source.bytes()) ? 3 : 0;
        return new SceneError(source.name(), 1, 1, message, source.lineText(start), help);
    }

    // ---- the byte-order mark ------------------------------------------------------------------

    private static boolean hasByteOrderMark(byte[] bytes) {
        return bytes.length >= 3 && (bytes[0] & 0xFF) == 0xEF && (bytes[1] & 0xFF) == 0xBB && (bytes[2] & 0xFF) == 0xBF;
    }
}
