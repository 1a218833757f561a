package rtd.io;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ThreadLocalRandom;
import rtd.image.Picture;
import rtd.scene.Scene;

/**
 * Input and output (paper, sections 4.1 and 4.3): reads a scene file, writes the picture as a
 * PNG ({@link PngEncoder}).
 */
public final class SceneIO {

    private SceneIO() {
    }

    /**
     * Reads the scene file at {@code path} (UTF-8). The OBJ files of its meshes are found relative
     * to the folder it is in.
     *
     * @throws SceneException if the file has mistakes; it lists them all
     * @throws IOException    if the file cannot be read
     */
    public static Scene readScene(Path path) throws SceneException, IOException {
        if (Files.isDirectory(path)) {
            throw new FileSystemException(path.toString(), null, "it is a folder, not a file");
        }
        Path folder = path.getParent() == null ? Path.of("") : path.getParent();
        return SceneParser.parse(new SourceText(path.toString(), Files.readAllBytes(path), folder));
    }

    /**
     * Reads a scene from {@code text}; {@code name} stands for the file in error messages. The
     * OBJ files of its meshes are found relative to the current directory.
     */
    public static Scene parseScene(String name, String text) throws SceneException {
        return parseScene(name, text, Path.of(""));
    }

    /** As {@link #parseScene(String, String)}, with the OBJ files of meshes found relative to {@code meshFolder}. */
    public static Scene parseScene(String name, String text, Path meshFolder) throws SceneException {
        return parseScene(name, text.getBytes(StandardCharsets.UTF_8), meshFolder);
    }

    /** Reads a scene from raw bytes; {@code name} stands for the file in error messages. */
    public static Scene parseScene(String name, byte[] bytes) throws SceneException {
        return parseScene(name, bytes, Path.of(""));
    }

    /** As {@link #parseScene(String, byte[])}, with the OBJ files of meshes found relative to {@code meshFolder}. */
    public static Scene parseScene(String name, byte[] bytes, Path meshFolder) throws SceneException {
        return SceneParser.parse(new SourceText(name, bytes, meshFolder));
    }

    /**
     * Writes {@code picture} as a 24-bit RGB PNG to {@code output}, compressing with up to
     * {@code threads} threads ({@link PngEncoder}), all or nothing: the PNG goes
     * to a temporary file in the same folder first and replaces {@code output} only when it is
     * complete, so a failed write leaves any earlier file exactly as it was.
     */
    public static void writePng(Picture picture, Path output, int threads) throws IOException {
        Path folder = output.toAbsolutePath().getParent();
        // Not Files.createTempFile: its file may be read by its owner only, and would stay so.
        // A random name, not a UUID: that would start a SecureRandom, slower than the whole write.
        Path temporary = folder.resolve("." + output.getFileName() + "."
                + Long.toHexString(ThreadLocalRandom.current().nextLong()) + ".tmp");
        // CREATE_NEW: should the name be taken, fail rather than overwrite (or later delete) that file.
        OutputStream file = Files.newOutputStream(temporary, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        try {
            try (OutputStream out = new BufferedOutputStream(file, 1 << 16)) {
                PngEncoder.write(picture, out, threads);
            }
            moveIntoPlace(temporary, output);
        } catch (IOException | RuntimeException | Error e) {
            Files.deleteIfExists(temporary);
            throw e;
        }
    }

    private static void moveIntoPlace(Path temporary, Path output) throws IOException {
        try {
            Files.move(temporary, output, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(temporary, output, StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
