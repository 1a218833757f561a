package rtd.io;

import java.awt.image.BufferedImage;
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
import java.util.UUID;
import javax.imageio.ImageIO;
import rtd.scene.Scene;

/**
 * Input and output (paper, sections 4.1 and 4.3): reads a scene file, writes the picture as a
 * PNG with {@code javax.imageio}.
 */
public final class SceneIO {

    private SceneIO() {
    }

    /**
     * Reads the scene file at {@code path} (UTF-8).
     *
     * @throws SceneException if the file has mistakes; it lists them all
     * @throws IOException    if the file cannot be read
     */
    public static Scene readScene(Path path) throws SceneException, IOException {
        if (Files.isDirectory(path)) {
            throw new FileSystemException(path.toString(), null, "it is a folder, not a file");
        }
        return SceneParser.parse(new SourceText(path.toString(), Files.readAllBytes(path)));
    }

    /** Reads a scene from {@code text}; {@code name} stands for the file in error messages. */
    public static Scene parseScene(String name, String text) throws SceneException {
        return SceneParser.parse(new SourceText(name, text.getBytes(StandardCharsets.UTF_8)));
    }

    /** Reads a scene from raw bytes; {@code name} stands for the file in error messages. */
    public static Scene parseScene(String name, byte[] bytes) throws SceneException {
        return SceneParser.parse(new SourceText(name, bytes));
    }

    /**
     * Loads the PNG writer of {@code javax.imageio} on a background thread, so that its one-time
     * start-up (about a tenth of a second) overlaps with reading the scene and rendering instead
     * of adding to them. Optional: {@link #writePng} works without it.
     */
    public static void preparePngWriter() {
        Thread thread = new Thread(() -> {
            ImageIO.setUseCache(false);
            try {
                ImageIO.write(new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB), "png", OutputStream.nullOutputStream());
            } catch (IOException e) {
                // only a warm-up: the real write reports any problem
            }
        }, "rtd-png-warm-up");
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * Writes {@code image} as a 24-bit RGB PNG to {@code output}, all or nothing: the PNG goes
     * to a temporary file in the same folder first and replaces {@code output} only when it is
     * complete, so a failed write leaves any earlier file exactly as it was.
     */
    public static void writePng(BufferedImage image, Path output) throws IOException {
        Path folder = output.toAbsolutePath().getParent();
        // Not Files.createTempFile: its file may be read by its owner only, and would stay so.
        Path temporary = folder.resolve("." + output.getFileName() + "." + UUID.randomUUID() + ".tmp");
        try {
            try (OutputStream out = new BufferedOutputStream(
                    Files.newOutputStream(temporary, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE), 1 << 16)) {
                ImageIO.setUseCache(false); // encode in memory, not through a cache file in /tmp
                if (!ImageIO.write(image, "png", out)) {
                    throw new IOException("this Java has no PNG writer");
                }
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
