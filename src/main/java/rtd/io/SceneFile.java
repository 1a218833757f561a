package rtd.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import rtd.geometry.IGeometry;
import rtd.image.Color;
import rtd.io.SceneContents.Found;
import rtd.scene.Scene;

/**
 * A scene file read into memory once, to be parsed at any clock (paper, section 4.1, Listing A.1; Part III,
 * "Expressions, named values and the clock"). Text that is not UTF-8 is refused at its first bad byte; every
 * mistake is reported with line and column, in file order. Once every line is read, the parse checks what only the
 * whole file can tell (one camera, one {@code ambient}, one definition per name) and gives the warnings of slips
 * that are no mistakes. The OBJ files of its meshes are read once for all frames.
 */
public final class SceneFile {

    private static final String CAMERA_EXAMPLE = "orthographic_camera:(0|0|20):(0|0|-1):(50)";

    private final String name;
    /** The file's bytes; null once {@link #once} has parsed them. */
    private byte[] bytes;
    private final Path folder;
    private final Map<Path, ObjMesh> meshes = new ConcurrentHashMap<>();
    private volatile boolean usesClock;
    /** The size of the parts a large file is read in, in parallel ({@link FileParts}). */
    private int partSize = FileParts.PART_SIZE;
    /** How many threads a parse may use; with one, the file is read in order on the calling thread. */
    private int threads = Runtime.getRuntime().availableProcessors();
    /** How many parts of the last parse were read in parallel and joined as they were. */
    int partsJoined;

    private SceneFile(String name, byte[] bytes, Path folder) {
        this.name = name;
        this.bytes = bytes;
        this.folder = folder;
    }

    /** The scene file at {@code path}, named {@code name} in messages, its meshes found from {@code folder}. */
    public static SceneFile read(Path path, String name, Path folder) throws IOException {
        if (Files.isDirectory(path)) {
            throw new FileSystemException(path.toString(), null, "it is a folder, not a file");
        }
        return new SceneFile(name, SceneIO.readBytes(path, SceneIO.MAX_SCENE_BYTES), folder);
    }

    /** The scene file at {@code path}, its meshes found from its folder. */
    public static SceneFile read(Path path) throws IOException {
        return read(path, path.toString(), path.getParent() == null ? Path.of("") : path.getParent());
    }

    /** A scene read from {@code in} (at most {@link SceneIO#MAX_SCENE_BYTES}), named {@code name}. */
    public static SceneFile read(InputStream in, String name) throws IOException {
        return new SceneFile(name, SceneIO.readBytes(in, name, (int) SceneIO.MAX_SCENE_BYTES), Path.of(""));
    }

    public static SceneFile of(String name, byte[] bytes, Path folder) {
        return new SceneFile(name, bytes, folder);
    }

    /** This file, read in parts of about {@code bytes} bytes: a small file, as a large one is. */
    SceneFile inPartsOf(int bytes) {
        partSize = bytes;
        return this;
    }

    /** This file, parsed with at most {@code threads} threads; with one, in order on the thread that asks. */
    public SceneFile onThreads(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be 1 or more, not " + threads);
        }
        this.threads = threads;
        return this;
    }

    public int size() {
        return bytes.length;
    }

    /** The scene at {@code clock}, or all its mistakes (a value may break a rule at some clocks only). */
    public Scene at(double clock, List<SceneError> warnings) throws SceneException {
        return parse(new Names(clock, new ClockedScene.Recorder()), warnings, false);
    }

    /** As {@link #at}, with the expression of every number that uses the clock, to export an animation as one file. */
    public ClockedScene withClock(double clock) throws SceneException {
        ClockedScene.Recorder recorder = new ClockedScene.Recorder();
        return recorder.scene(parse(new Names(clock, recorder), null, false));
    }

    /** The scene at clock 0, parsed once: the bytes go with the parse ({@link SourceText#close}), before the render. */
    public Scene once(List<SceneError> warnings) throws SceneException {
        return parse(new Names(0, new ClockedScene.Recorder()), warnings, true);
    }

    /** Whether a number of the file used the clock, in a parse so far; if none does, every frame is the same. */
    public boolean usesClock() {
        return usesClock;
    }

    private Scene parse(Names names, List<SceneError> warnings, boolean once) throws SceneException {
        // Taken from the field, not kept in a local variable, which would hold them to the end of the parse.
        try (SourceText source = new SourceText(name, once ? takeBytes() : bytes, folder, meshes)) {
            int start = TextBytes.startsWithByteOrderMark(source.bytes()) ? 3 : 0;
            FileParts parts = FileParts.of(source, start, partSize, threads);
            SceneContents contents = new SceneContents(parts.objectsAtMost(0, parts.count()));
            partsJoined = parts.read(new StatementReader(source, start, 1, contents, names), contents, names);
            return join(source, start, contents, warnings);
        } finally { // a failed parse tells too: a value may break its rule at some clocks only
            usesClock |= names.clockUsed;
        }
    }

    private byte[] takeBytes() {
        byte[] taken = bytes;
        bytes = null;
        return taken;
    }

    /** The scene the contents make, or every mistake in them, ordered by place. */
    private static Scene join(SourceText source, int start, SceneContents contents, List<SceneError> warnings)
            throws SceneException {
        List<Found> errors = contents.errors;
        SceneError numbered = contents.firstLineNumber; // the lines that start with a line number: one mistake
        if (numbered != null) {
            int more = contents.lineNumbers - 1;
            errors.add(numbered.saying(numbered.message() + (more == 0 ? "" : more == 1 ? ", as does 1 more line"
                    : ", as do " + more + " more lines"), numbered.help()).found());
        }
        onlyOne(contents.ambients, "a second 'ambient': a scene has one background colour", "the first 'ambient'",
                errors);
        onlyOne(contents.cameras, "a second camera: a scene has one", "the first camera", errors);
        DefinedNames names = new DefinedNames(contents, errors);
        Set<String> named = new HashSet<>(contents.namedAtOnce);
        List<IGeometry> objects = contents.allObjects(names, named);
        if (errors.isEmpty() && contents.statementCount == 0) {
            errors.add(source.errorAt(1, start, start, "the scene is empty: it has no statements, only blanks and "
                    + "comments", "a scene needs at least a camera, such as " + CAMERA_EXAMPLE).found());
        } else if (errors.isEmpty() && contents.cameras.isEmpty()) {
            errors.add(source.errorAt(1, start, start, "the scene has no camera",
                    "add a line such as " + CAMERA_EXAMPLE).found());
        }
        if (!errors.isEmpty()) {
            errors.sort(Comparator.comparingInt(Found::line).thenComparingInt(Found::column));
            throw new SceneException(errors.stream().limit(SceneException.MAX_ERRORS).map(Found::error)
                    .toList(), errors.size() > SceneException.MAX_ERRORS);
        }
        if (warnings != null) {
            boolean lit = !contents.lights.isEmpty();
            warnings.addAll(names.warnings(named, lit));
            if (lit) {
                contents.litWarnings.stream().sorted(Comparator.comparingInt(SceneError::line))
                        .limit(SceneException.MAX_ERRORS).forEach(warnings::add);
            }
        }
        Color ambient = contents.ambients.isEmpty() ? Color.BLACK : contents.ambients.get(0).value();
        return new Scene(ambient, contents.cameras.get(0).value(), objects, contents.lights);
    }

    /** An error at each of {@code found} after the first, which {@code first} names in the help. */
    private static void onlyOne(List<? extends SceneContents.Located<?>> found, String second, String first,
            List<Found> errors) {
        for (var located : found.subList(Math.min(1, found.size()), found.size())) {
            errors.add(located.place().saying(second, first + " is at line " + found.get(0).place().line()).found());
        }
    }
}
