package rtd.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import rtd.scene.Scene;

/**
 * A scene file read into memory once, to be parsed at any clock (Part III, "Expressions, named values and the
 * clock"): each frame of an animation is the file parsed at its own clock, and the OBJ files of its meshes are
 * read once for all frames. After the first parse it tells whether any number uses the clock; if none does,
 * every frame is the same picture. It is the one way in to reading a scene: {@link SceneIO} reads one at clock 0.
 */
public final class SceneFile {

    private final String name;
    /** The file's bytes; null once {@link #once} has parsed them. */
    private byte[] bytes;
    private final Path folder;
    private final Map<Path, ObjMesh> meshes = new ConcurrentHashMap<>();
    private volatile boolean usesClock;

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
        return new SceneFile(name, SceneFileReader.read(path, SceneIO.MAX_SCENE_BYTES), folder);
    }

    /** The scene file at {@code path}, its meshes found from its folder. */
    public static SceneFile read(Path path) throws IOException {
        return read(path, path.toString(), path.getParent() == null ? Path.of("") : path.getParent());
    }

    /** A scene read from {@code in} (at most {@link SceneIO#MAX_SCENE_BYTES}), named {@code name}. */
    public static SceneFile read(InputStream in, String name) throws IOException {
        return new SceneFile(name, SceneFileReader.read(in, name, (int) SceneIO.MAX_SCENE_BYTES), Path.of(""));
    }

    /** A scene of {@code bytes}, named {@code name} in messages, its meshes found from {@code folder}. */
    public static SceneFile of(String name, byte[] bytes, Path folder) {
        return new SceneFile(name, bytes, folder);
    }

    public int size() {
        return bytes.length;
    }

    /**
     * The scene at {@code clock}; its slips go to {@code warnings} (null: dropped).
     *
     * @throws SceneException with every mistake, a value that breaks a rule at this clock among them
     */
    public Scene at(double clock, List<SceneError> warnings) throws SceneException {
        return parse(new Names(clock, new ClockedScene.Recorder()), warnings);
    }

    /**
     * The scene at {@code clock} with the expression of every number that uses the clock, for writing an animation
     * as one POV-Ray file; read as {@link #at} reads it, with that table besides.
     *
     * @throws SceneException with every mistake, a value that breaks a rule at this clock among them
     */
    public ClockedScene withClock(double clock) throws SceneException {
        ClockedScene.Recorder recorder = new ClockedScene.Recorder();
        return recorder.scene(parse(new Names(clock, recorder), null));
    }

    /**
     * The scene at clock 0, for a file read to be parsed once: this file lets its bytes go as the parse starts, so
     * that they go with the parse's own ({@link SourceText#close}), before the render of a large scene.
     */
    Scene once(List<SceneError> warnings) throws SceneException {
        return parse(new Names(0, new ClockedScene.Recorder()), warnings, true);
    }

    private Scene parse(Names names, List<SceneError> warnings) throws SceneException {
        return parse(names, warnings, false);
    }

    private Scene parse(Names names, List<SceneError> warnings, boolean once) throws SceneException {
        // Taken from the field, not kept in a local variable, which would hold them to the end of the parse.
        try (SourceText source = new SourceText(name, once ? takeBytes() : bytes, folder, meshes)) {
            return SceneParser.parse(source, names, warnings);
        } finally { // a failed parse tells too: a value may break its rule at some clocks only
            usesClock |= names.clockUsed;
        }
    }

    private byte[] takeBytes() {
        byte[] taken = bytes;
        bytes = null;
        return taken;
    }

    /** Whether a number of the file used the clock, in a parse so far. */
    public boolean usesClock() {
        return usesClock;
    }
}
