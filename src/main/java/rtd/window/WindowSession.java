package rtd.window;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Supplier;
import rtd.explain.PixelExplanation;
import rtd.explain.RayTree;
import rtd.image.Picture;
import rtd.io.ImageFormat;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.math.Vector3f;
import rtd.render.Tracer;
import rtd.scene.Scene;
import rtd.view.View;

/**
 * What the window does, without its Swing parts: the scene and its moved camera, the view, the selected pixel, and
 * the renders. It lives on the window's thread (Swing's event thread, {@code ui}); renders run on the
 * {@link RenderLoop}, explanations and saves on a thread of their own, and what they find comes back through
 * {@code ui} to the {@link Display}.
 */
final class WindowSession implements AutoCloseable {

    private static final View[] VIEWS = View.values();

    private final WindowSetup setup;
    private final Display display;
    private final Executor ui;
    private final RenderLoop renders;
    private final FrameRenderer renderer;
    private final ExecutorService helper = Executors.newSingleThreadExecutor(runnable -> {
        Thread thread = new Thread(runnable, "rtd-window-explain");
        thread.setDaemon(true);
        return thread;
    });
    private Scene file;
    private CameraController camera;
    private View view;
    private int[] selected;
    private int[] underMouse;
    private FrameRenderer.Pass shown;
    /** Counts the frames asked for: a pass of an older one is not shown. */
    private long generation;
    private long shownGeneration = -1;
    /** The blocks and time of the last moving frame shown, for the next one's blocks. */
    private int movingBlock = 2;
    /** Whether the panel is to show the view's scale once its full picture is drawn. */
    private boolean legendWanted;
    private long movingNanos;
    /** The tracers for any camera of the scene {@link #anyFor} is for; touched on the render thread only. */
    private Scene anyScene;
    private Supplier<Tracer> anyTracers;

    WindowSession(WindowSetup setup, Scene scene, Display display, Executor ui) {
        this.setup = setup;
        this.display = display;
        this.ui = ui;
        this.renderer = new FrameRenderer(setup.engine());
        this.renders = new RenderLoop(e -> ui.execute(() -> display.panel("rtd: internal error while rendering: " + e
                + ". This is a bug in rtd; please report it with the scene.")));
        this.file = scene;
        this.camera = new CameraController(scene.camera());
    }

    /** The first picture, coarse at once, then refined. */
    void start() {
        display.panel(Keys.HELP);
        render(Refinement.STILL);
    }

    /** The scene with the window's camera. */
    Scene scene() {
        return new Scene(file.ambient(), camera.camera(), file.objects(), file.lights());
    }

    CameraController camera() {
        return camera;
    }

    /** The last pass shown, or null. */
    FrameRenderer.Pass shown() {
        return shown;
    }

    /** Renders the scene as it is now in {@code refinement}'s passes, cancelling a still render in progress. */
    void render(Refinement refinement) {
        long frame = ++generation;
        Scene scene = scene();
        Scene objects = file;
        FrameRenderer.Frame request = new FrameRenderer.Frame(scene, view, setup.width(), setup.height(),
                setup.samples(), setup.threads(), refinement);
        boolean moving = !refinement.endsFull();
        FrameRenderer.Listener listener = pass -> ui.execute(() -> show(frame, pass, moving));
        renders.submit(() -> renderer.render(request, anyFor(objects), new ProgressiveBuffer(setup.width(),
                setup.height()), listener), !moving);
    }

    /** The tracers for any camera, built once for each scene read (on the render thread). */
    private Supplier<Tracer> anyFor(Scene scene) {
        if (anyScene != scene) {
            anyTracers = setup.engine().forAnyCamera(scene, setup.width(), setup.height());
            anyScene = scene;
        }
        return anyTracers;
    }

    private void show(long frame, FrameRenderer.Pass pass, boolean moving) {
        if (frame < shownGeneration) {
            return; // a newer frame is already on screen
        }
        if (moving) {
            movingBlock = pass.block();
            movingNanos = pass.nanos();
        }
        shownGeneration = frame;
        shown = pass;
        if (legendWanted && pass.block() == 1 && frame == generation && selected == null) {
            legendWanted = false;
            display.panel(pass.legend());
        }
        display.picture(pass.picture());
        status();
    }

    private void status() {
        if (shown != null) {
            display.status(StatusText.of(setup.width(), setup.height(), shown.nanos(), shown.rays(), shown.block(),
                    underMouse, view == null ? "picture" : view.name()));
        }
    }

    /** The pixel under the mouse, or null, for the status line. */
    void mouseAt(int[] pixel) {
        underMouse = pixel;
        status();
    }

    /** The point to orbit around and pan at ({@link Pivot}). */
    Vector3f pivot() {
        return Pivot.of(scene(), setup.width(), setup.height());
    }

    /** The mouse dragged by {@code dx, dy} pixels of the picture: an orbit about {@code pivot}, or a pan. */
    void drag(double dx, double dy, boolean pan, Vector3f pivot) {
        if (pan) {
            camera.pan(dx, dy, pivot, setup.width());
        } else {
            camera.orbit(-dx * Math.PI / setup.width(), dy * Math.PI / setup.width(), pivot);
        }
        moved();
    }

    /** The wheel turned by {@code clicks} (towards the user: negative, zooms in). */
    void wheel(double clicks) {
        camera.zoom(-clicks, pivot());
        moved();
    }

    private void moved() {
        display.rays(List.of()); // the selected pixel's rays follow once the camera rests
        render(Refinement.moving(movingBlock, movingNanos));
    }

    /** The mouse rests after moving the camera: the full picture, and the selected pixel's rays again. */
    void rested() {
        render(Refinement.RESTED);
        explainSelected();
    }

    /** {@code R}: the file's camera. */
    void resetCamera() {
        camera.reset();
        render(Refinement.STILL);
        explainSelected();
    }

    /** Keys 1 to 5: the picture (null) or a view, whose scale the panel shows once it is drawn. */
    void show(View shownView) {
        view = shownView;
        legendWanted = view != null;
        render(Refinement.STILL);
    }

    /** {@code V}: the next view, after the last the picture. */
    void nextView() {
        show(view == null ? VIEWS[0] : view.ordinal() + 1 < VIEWS.length ? VIEWS[view.ordinal() + 1] : null);
    }

    /** A click on pixel (x, y): its explanation in the panel and its rays over the picture. */
    void select(int[] pixel) {
        if (pixel == null || pixel[1] >= setup.height()) {
            return; // outside the picture, or on a view's legend
        }
        selected = pixel;
        explainSelected();
    }

    /** {@code Esc}: no pixel selected. */
    void deselect() {
        selected = null;
        display.rays(List.of());
        display.panel(Keys.HELP);
    }

    private void explainSelected() {
        if (selected == null) {
            return;
        }
        int x = selected[0];
        int y = selected[1];
        Scene scene = scene();
        int w = setup.width();
        int h = setup.height();
        helper.execute(() -> {
            String text = "pixel (" + x + ", " + y + ") of the " + w + " × " + h + " picture of " + setup.scene()
                    + " (what --explain " + x + "," + y + " prints at this size and camera):\n\n"
                    + PixelExplanation.of(scene, x, y, w, h);
            List<RayTreeProjection.Line> lines = new RayTreeProjection(scene.camera(), w, h)
                    .lines(RayTree.of(scene, x, y, w, h));
            ui.execute(() -> {
                if (selected != null && selected[0] == x && selected[1] == y) {
                    display.panel(text);
                    display.rays(lines);
                }
            });
        });
    }

    /** {@code C}: the camera as a scene line, on the clipboard and in the panel. */
    void copyCamera() {
        String line = CameraLine.of(camera.camera());
        display.copy(line);
        display.panel("The camera, copied to the clipboard: paste it in place of the scene's camera line; the scene "
                + "then renders this picture at " + setup.width() + " × " + setup.height() + ":\n\n" + line + "\n");
    }

    /** {@code Ctrl+S}: the full picture (or view) as shown, written as {@code -o} writes, beside the scene. */
    void save() {
        if (shown == null || shown.block() != 1 || shownGeneration != generation) {
            display.panel("The picture is still being rendered; save again once the status line shows no blocks.");
            return;
        }
        Picture picture = shown.picture();
        Path target = setup.savedPicture();
        helper.execute(() -> {
            String said;
            try {
                SceneIO.writeImage(picture, ImageFormat.PNG, target, done -> { });
                said = "Saved the picture as " + target + " (" + picture.width() + " × " + picture.height() + ").";
            } catch (IOException | RuntimeException e) {
                said = "rtd: cannot write '" + target + "': " + e.getMessage();
            }
            String message = said;
            ui.execute(() -> display.panel(message));
        });
    }

    /** The scene file was saved: read again, or its mistakes shown while the last good picture stays. */
    void reloaded(Scene scene, SceneException mistakes, IOException unreadable) {
        if (scene == null) {
            String why = mistakes != null ? mistakes.report() : "rtd: " + unreadable.getMessage() + "\n";
            display.panel(why + "\nThe last good picture stays; fix the scene and save it again.");
            return;
        }
        boolean sameCamera = CameraLine.of(scene.camera()).equals(CameraLine.of(file.camera()));
        file = scene;
        if (!sameCamera) {
            camera = new CameraController(scene.camera()); // the file's new camera
        }
        render(Refinement.STILL);
        if (selected != null) {
            explainSelected();
        } else {
            display.panel(Keys.HELP);
        }
    }

    @Override
    public void close() {
        renders.close();
        helper.shutdownNow();
    }
}
