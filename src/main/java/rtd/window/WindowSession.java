package rtd.window;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.function.Consumer;
import rtd.camera.ICamera;
import rtd.io.SceneException;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.view.View;
import rtd.window.WindowSetup.ClockedScene;

/**
 * What the window does, without its Swing parts: the scene and its moved camera, the clock ({@link ClockControl}), the
 * view, the selected pixel, and the renders. It lives on the window's thread (Swing's event thread, {@code ui});
 * renders run on the {@link RenderLoop}, explanations and saves on a thread of their own ({@link SideJobs}), and what
 * they find comes back through {@code ui} to the {@link Display}.
 */
final class WindowSession implements AutoCloseable {

    private static final View[] VIEWS = View.values();

    private final WindowSetup setup;
    private final Display display;
    private final Executor ui;
    private final RenderLoop renders;
    private final FrameRenderer renderer;
    private final SideJobs jobs;
    private final ClockControl clock;
    /** The file's last good scene, at the clock shown. */
    private Scene file;
    /** Whether the panel shows a mistake, to give way to the keys or the explanation once the scene is good. */
    private boolean showsMistake;
    private CameraController camera;
    private View view;
    private int[] selected;
    private int[] underMouse;
    private FrameRenderer.Pass shown;
    /** Counts the frames asked for: a pass of an older one is not shown. */
    private long generation;
    private long shownGeneration = -1;
    /** The next moving frame's blocks, from the blocks and time of the last moving frame shown. */
    private List<Integer> nextMoving = FrameRenderer.MOVING;
    /** Whether the panel is to show the view's scale once its full picture is drawn. */
    private boolean legendWanted;

    /** A session on {@code scene}, which is {@code source} parsed at {@code setup}'s clock. */
    WindowSession(WindowSetup setup, ClockedScene source, Scene scene, Display display, Executor ui) {
        this.setup = setup;
        this.display = display;
        this.ui = ui;
        this.renderer = new FrameRenderer(setup.engine(), setup.width(), setup.height(), setup.samples(), setup.threads());
        this.renders = new RenderLoop(e -> ui.execute(() -> display.panel("rtd: internal error while rendering: " + e
                + ". This is a bug in rtd; please report it with the scene.")));
        this.jobs = new SideJobs(ui);
        this.clock = new ClockControl(this, display, source, setup.clock());
        this.file = scene;
        this.camera = new CameraController(scene.camera());
    }

    void start() {
        display.panel(SceneWindow.HELP);
        clock.showSlider();
        render(FrameRenderer.STILL);
    }

    /** The scene with the window's camera. */
    Scene scene() {
        return new Scene(file.ambient(), camera.camera(), file.objects(), file.lights());
    }

    CameraController camera() {
        return camera;
    }

    ClockControl clock() {
        return clock;
    }

    FrameRenderer.Pass shown() {
        return shown;
    }

    /** Renders the scene as it is now in passes of {@code blocks}, cancelling a still render in progress. */
    void render(List<Integer> blocks) {
        long frame = ++generation;
        Scene objects = file;
        ICamera eye = camera.camera();
        View shownView = view;
        boolean moving = !blocks.contains(1);
        Consumer<FrameRenderer.Pass> listener = pass -> ui.execute(() -> show(frame, pass, moving));
        renders.submit(() -> renderer.render(objects, eye, shownView, blocks, listener), !moving);
    }

    private void show(long frame, FrameRenderer.Pass pass, boolean moving) {
        if (frame < shownGeneration) {
            return; // a newer frame is already on screen
        }
        if (moving) {
            nextMoving = FrameRenderer.moving(pass.block(), pass.nanos());
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

    void status() {
        if (shown != null) {
            display.status(shown.status(setup.width(), setup.height(), underMouse,
                    (view == null ? "picture" : view.name()) + clock.status()));
        }
    }

    void mouseAt(int[] pixel) {
        underMouse = pixel;
        status();
    }

    Vector3f pivot() {
        return CameraController.pivot(scene(), setup.width(), setup.height());
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
        render(nextMoving);
    }

    /** The mouse rests after moving the camera: the full picture, and the selected pixel's rays again. */
    void rested() {
        render(FrameRenderer.RESTED);
        explainSelected();
    }

    /** {@code R}: the file's camera at the clock shown. */
    void resetCamera() {
        camera = new CameraController(file.camera());
        render(FrameRenderer.STILL);
        explainSelected();
    }

    /** Keys 1 to 5: the picture (null) or a view, whose scale the panel shows once it is drawn. */
    void show(View shownView) {
        view = shownView;
        legendWanted = view != null;
        render(FrameRenderer.STILL);
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
        display.panel(SceneWindow.HELP);
    }

    private void explainSelected() {
        if (selected == null) {
            return;
        }
        int[] pixel = selected;
        jobs.explain(scene(), setup.scene(), pixel[0], pixel[1], setup.width(), setup.height(), (text, lines) -> {
            if (Arrays.equals(selected, pixel)) {
                display.panel(text);
                display.rays(lines);
            }
        });
    }

    /** {@code C}: the camera as a scene line, on the clipboard and in the panel. */
    void copyCamera() {
        String line = CameraController.line(camera.camera());
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
        jobs.save(shown.picture(), setup.savedPicture(), display::panel);
    }

    /** The file saved again: parsed at the clock shown, or its mistakes shown; the file's camera if it changed. */
    void reloaded(ClockedScene read) {
        Scene scene;
        try {
            scene = clock.read(read);
        } catch (SceneException e) {
            mistake(e.report(), "");
            return;
        }
        if (!sameCamera(scene.camera(), file.camera())) {
            camera = new CameraController(scene.camera()); // the file's new camera
        }
        file = scene;
        render(FrameRenderer.STILL);
        panelAgain();
    }

    /** The scene at a new clock, the camera following the file's if the user has not moved it; {@code full} at rest. */
    void atClock(Scene scene, boolean full) {
        if (sameCamera(camera.camera(), file.camera())) {
            camera = new CameraController(scene.camera()); // not moved by the user: it follows the file's
        }
        file = scene;
        if (showsMistake) {
            panelAgain();
        }
        if (full) {
            rested();
        } else {
            moved();
        }
    }

    /** Whether two cameras write the same scene line, and so draw the same picture. */
    private static boolean sameCamera(ICamera a, ICamera b) {
        return CameraController.line(a).equals(CameraController.line(b));
    }

    /** A mistake's {@code report} in the panel, the last good picture kept; {@code orClock} adds a way out. */
    void mistake(String report, String orClock) {
        showsMistake = true;
        display.panel(report + "\nThe last good picture stays; fix the scene and save it again" + orClock + ".");
    }

    /** The panel's keys, or the selected pixel's explanation, again, in place of a mistake. */
    private void panelAgain() {
        showsMistake = false;
        if (selected != null) {
            explainSelected();
        } else {
            display.panel(SceneWindow.HELP);
        }
    }

    @Override
    public void close() {
        renders.close();
        jobs.close();
    }
}
