package rtd.io;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.function.DoubleConsumer;
import rtd.image.Picture;
import rtd.scene.Scene;

/**
 * Input and output (paper, sections 4.1 and 4.3): reads a scene file at clock 0 (a {@link SceneFile} read
 * once), writes the picture as a PNG, or in another format that {@code javax.imageio} writes
 * ({@link ImageFormat#write}). Every warning list may be null: the warnings are dropped.
 */
public final class SceneIO {

    /** The name of standard input in messages, as compilers call it. */
    public static final String STDIN_NAME = "<stdin>";
    /** The largest scene file rtd reads, 1 GiB: about 20 million spheres. */
    public static final long MAX_SCENE_BYTES = 1L << 30;

    private SceneIO() {
    }

    /**
     * Reads the scene file at {@code path} (UTF-8) in bounded memory and time ({@link SceneFileReader}); its
     * meshes' OBJ files are found from its folder.
     *
     * @throws SceneException if the file has mistakes; it lists them all
     * @throws IOException    if the file cannot be read
     */
    public static Scene readScene(Path path) throws SceneException, IOException {
        return readScene(path, null);
    }

    /** As {@link #readScene(Path)}, adding to {@code warnings} the likely slips that are no mistakes. */
    public static Scene readScene(Path path, List<SceneError> warnings) throws SceneException, IOException {
        return SceneFile.read(path).once(warnings);
    }

    /** As {@link #readScene(Path, List)}, named {@code name} in messages: {@code <stdin>} for {@code /dev/stdin}. */
    public static Scene readScene(Path path, String name, List<SceneError> warnings) throws SceneException, IOException {
        return SceneFile.read(path, name, Path.of("")).once(warnings);
    }

    /** Reads a scene from {@code in} (all of it, up to {@link #MAX_SCENE_BYTES}), where there is no {@code /dev/stdin}. */
    public static Scene readScene(InputStream in, String name, List<SceneError> warnings) throws SceneException, IOException {
        return SceneFile.read(in, name).once(warnings);
    }

    /** Reads a scene from {@code text}, named {@code name} in messages; meshes are found from the current directory. */
    public static Scene parseScene(String name, String text) throws SceneException {
        return parseScene(name, text, Path.of(""));
    }

    /** As {@link #parseScene(String, String)}, with the OBJ files of meshes found relative to {@code meshFolder}. */
    public static Scene parseScene(String name, String text, Path meshFolder) throws SceneException {
        return parseScene(name, text.getBytes(StandardCharsets.UTF_8), meshFolder, null);
    }

    /** As {@link #parseScene(String, String)}, adding the scene's warnings to {@code warnings}. */
    public static Scene parseScene(String name, String text, List<SceneError> warnings) throws SceneException {
        return parseScene(name, text.getBytes(StandardCharsets.UTF_8), Path.of(""), warnings);
    }

    /** Reads a scene from raw bytes, named {@code name} in messages, meshes found from {@code meshFolder}. */
    public static Scene parseScene(String name, byte[] bytes, Path meshFolder, List<SceneError> warnings)
            throws SceneException {
        return SceneFile.of(name, bytes, meshFolder).once(warnings);
    }

    /**
     * Writes {@code picture} to {@code output} all or nothing: into a temporary file beside it
     * ({@link TemporaryFiles}), which replaces {@code output} only when complete and is removed on failure.
     * {@code progress} hears the fraction written.
     */
    public static void writeImage(Picture picture, ImageFormat format, Path output, DoubleConsumer progress)
            throws IOException {
        TemporaryFiles.replace(output, out -> format.write(picture, out, progress));
    }

    /** Writes {@code text} in UTF-8 to {@code output} as {@link #writeImage} writes a picture: whole, or not at all. */
    public static void writeText(String text, Path output) throws IOException {
        // Encoded as it is written, not as one array: the export of a large scene is tens of megabytes.
        TemporaryFiles.replace(output, out -> {
            Writer writer = new OutputStreamWriter(out, StandardCharsets.UTF_8);
            writer.write(text);
            writer.flush();
        });
    }

    /**
     * Writes {@code picture} into {@code device}, a FIFO or a device such as /dev/null, opened for writing
     * only: never created, replaced or truncated.
     */
    public static void writeImageInto(Picture picture, ImageFormat format, Path device, DoubleConsumer progress)
            throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(device, StandardOpenOption.WRITE), 1 << 16)) {
            format.write(picture, out, progress);
        }
    }
}
