package rtd.window;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import rtd.explain.PixelExplanation;
import rtd.explain.RayTree;
import rtd.image.Picture;
import rtd.io.ImageFormat;
import rtd.io.SceneIO;
import rtd.scene.Scene;

/**
 * The window's slower answers, on a thread of their own so that neither the window nor its renders wait: a pixel's
 * explanation with its ray tree, and a saved picture. Each result is handed to the window's thread, {@code ui}.
 */
final class SideJobs implements AutoCloseable {

    private final ExecutorService helper = Executors.newSingleThreadExecutor(job -> RenderLoop.daemon(job,
            "rtd-window-explain"));
    private final Executor ui;

    SideJobs(Executor ui) {
        this.ui = ui;
    }

    /**
     * Pixel (x, y) of {@code scene}'s {@code w × h} picture as {@code --explain} tells it, the scene named
     * {@code name}, and its ray tree in image coordinates: both to {@code then}.
     */
    void explain(Scene scene, Path name, int x, int y, int w, int h,
            BiConsumer<String, List<RayTreeProjection.Line>> then) {
        helper.execute(() -> {
            String text = "pixel (" + x + ", " + y + ") of the " + w + " × " + h + " picture of " + name
                    + " (what --explain " + x + "," + y + " prints at this size and camera):\n\n"
                    + PixelExplanation.of(scene, x, y, w, h);
            List<RayTreeProjection.Line> lines = new RayTreeProjection(scene.camera(), w, h)
                    .lines(RayTree.of(scene, x, y, w, h));
            ui.execute(() -> then.accept(text, lines));
        });
    }

    /** {@code picture} written to {@code target} as {@code -o} writes it; what happened, in a sentence, to {@code said}. */
    void save(Picture picture, Path target, Consumer<String> said) {
        helper.execute(() -> {
            String message;
            try {
                SceneIO.writeImage(picture, ImageFormat.PNG, target, done -> { });
                message = "Saved the picture as " + target + " (" + picture.width() + " × " + picture.height() + ").";
            } catch (IOException | RuntimeException e) {
                message = "rtd: cannot write '" + target + "': " + e.getMessage();
            }
            String told = message;
            ui.execute(() -> said.accept(told));
        });
    }

    @Override
    public void close() {
        helper.shutdownNow();
    }
}
