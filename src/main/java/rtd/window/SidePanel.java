package rtd.window;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import rtd.camera.ICamera;
import rtd.explain.PixelExplanation;
import rtd.explain.RayTree;
import rtd.image.Picture;
import rtd.io.ImageFormat;
import rtd.io.SceneIO;
import rtd.scene.Scene;

/**
 * The window's panel of text, without Swing: the keys ({@link #HELP}), a selected pixel's explanation as
 * {@code --explain} tells it with its rays over the picture, the copied camera, a saved picture, a scene's mistakes.
 * The slower answers, an explanation and a save, run on a thread of their own, so that neither the window nor its
 * renders wait; each comes back through {@code ui}, and an explanation shows only if its pixel is still selected. Used
 * on the window's thread.
 */
final class SidePanel implements AutoCloseable {

    /** The window's keys and mouse, as its panel shows them before a pixel is selected (and the README's table). */
    static final String HELP = String.join("\n",
            "rtd's window: click a pixel to see what rtd does for it.",
            "",
            "  drag        orbit around what the centre pixel sees",
            "  right drag  pan (or Shift + drag)",
            "  wheel       zoom",
            "  click       explain the pixel, its rays over the picture",
            "  1 to 5      picture, cost, depth, normal, id (V: next)",
            "  R           the file's camera again",
            "  C           copy the camera as a scene line",
            "  P           play the clock, 0 to 1 in 5 s, or pause",
            "  Ctrl+S      save the picture as NAME-window.png",
            "  Esc         no pixel selected",
            "  Q           quit",
            "",
            "Saving the scene file renders it again. A scene that uses clock",
            "has a clock slider above this panel.",
            "");

    private final ExecutorService helper = Executors.newSingleThreadExecutor(job -> FrameRenderer.daemon(job,
            "rtd-window-explain"));
    private final WindowSetup setup;
    private final Display display;
    private final Executor ui;
    private int[] selected;
    /** Whether the panel shows a mistake, to give way to the keys or the explanation once the scene is good. */
    private boolean showsMistake;

    SidePanel(WindowSetup setup, Display display, Executor ui) {
        this.setup = setup;
        this.display = display;
        this.ui = ui;
    }

    boolean selected() {
        return selected != null;
    }

    /** A click on {@code pixel} (x, y) of {@code scene}'s picture: its explanation and its rays. */
    void select(int[] pixel, Scene scene) {
        if (pixel != null && pixel[1] < setup.height()) { // not outside the picture, nor on a view's legend
            selected = pixel;
            explain(scene);
        }
    }

    /** The selected pixel of {@code scene}, if any, explained (again), and its ray tree in image coordinates. */
    void explain(Scene scene) {
        int[] pixel = selected;
        if (pixel == null) {
            return;
        }
        int x = pixel[0];
        int y = pixel[1];
        int w = setup.width();
        int h = setup.height();
        helper.execute(() -> {
            String text = "pixel (" + x + ", " + y + ") of the " + w + " × " + h + " picture of " + setup.scene()
                    + " (what --explain " + x + "," + y + " prints at this size and camera):\n\n"
                    + PixelExplanation.of(scene, x, y, w, h);
            List<RayTreeProjection.Line> lines = new RayTreeProjection(scene.camera(), w, h)
                    .lines(RayTree.of(scene, x, y, w, h));
            ui.execute(() -> {
                if (Arrays.equals(selected, pixel)) {
                    display.panel(text);
                    display.rays(lines);
                }
            });
        });
    }

    void deselect() {
        selected = null;
        display.rays(List.of());
        display.panel(HELP);
    }

    /** {@code camera} as a scene line, on the clipboard and in the panel. */
    void copy(ICamera camera) {
        String line = CameraController.line(camera);
        display.copy(line);
        display.panel("The camera, copied to the clipboard: paste it in place of the scene's camera line; the scene "
                + "then renders this picture at " + setup.width() + " × " + setup.height() + ":\n\n" + line + "\n");
    }

    /** The picture {@code shown} written as {@code -o} writes it, beside the scene, if it is the newest in full. */
    void save(FrameRenderer.Pass shown, boolean newest) {
        if (shown == null || shown.block() != 1 || !newest) {
            display.panel("The picture is still being rendered; save again once the status line shows no blocks.");
            return;
        }
        Picture picture = shown.picture();
        Path target = setup.savedPicture();
        helper.execute(() -> {
            String message;
            try {
                SceneIO.writeImage(picture, ImageFormat.PNG, target, done -> { });
                message = "Saved the picture as " + target + " (" + picture.width() + " × " + picture.height() + ").";
            } catch (IOException | RuntimeException e) {
                message = "rtd: cannot write '" + target + "': " + e.getMessage();
            }
            String told = message;
            ui.execute(() -> display.panel(told));
        });
    }

    /** A mistake's {@code report}, the last good picture kept; {@code orClock} adds a way out. */
    void mistake(String report, String orClock) {
        showsMistake = true;
        display.panel(report + "\nThe last good picture stays; fix the scene and save it again" + orClock + ".");
    }

    /** The keys, or the selected pixel of the good {@code scene} explained, in place of a mistake if one shows. */
    void fixed(Scene scene, boolean always) {
        if (showsMistake || always) {
            showsMistake = false;
            if (selected != null) {
                explain(scene);
            } else {
                display.panel(HELP);
            }
        }
    }

    @Override
    public void close() {
        helper.shutdownNow();
    }
}
