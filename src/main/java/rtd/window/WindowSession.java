package rtd.window;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Executor;
import java.util.function.Consumer;
import rtd.camera.ICamera;
import rtd.image.Picture;
import rtd.io.SceneException;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.view.View;
import rtd.window.WindowSetup.ClockedScene;

/**
 * What the window does, without its Swing parts: the scene file at the clock shown, the camera as the mouse moved it,
 * the view, the selected pixel, and the renders. It lives on the window's thread (Swing's event thread, {@code ui});
 * renders run on the {@link RenderLoop}, explanations and saves on their own thread ({@link SideJobs}), and what they
 * find comes back through {@code ui} to the {@link Display}.
 *
 * <p>The clock slider and {@code P} parse the file read at the last save again at each clock; a value that breaks at a
 * clock (a radius negative at clock = 0.75) shows as a saved mistake does, and the last good picture stays. Playing
 * runs the clock from where it is towards 1 and round to 0, one pass in {@link #PASS_NANOS}, as an animation loops:
 * time, not frames, moves it, so a slow scene plays at the same pace in fewer frames. A camera the user has not moved
 * follows the file's at each clock.
 */
final class WindowSession implements AutoCloseable {

    /** One pass of the played clock from 0 to 1: 5 seconds. */
    static final long PASS_NANOS = 5_000_000_000L;

    /** What the window shows, told by its session; called on the window's thread only. */
    interface Display {

        /** The picture, or a view with its legend below it. */
        void picture(Picture picture);

        /** The selected pixel's ray tree, in image coordinates; empty for none. */
        void rays(List<RayTreeProjection.Line> lines);

        /** The side panel's text: the explanation, the copied camera, a scene's mistakes, the keys. */
        void panel(String text);

        void status(String text);

        /** The clock slider at {@code clock}, or hidden for null: the scene does not use {@code clock}. */
        void clock(Double clock);

        void copy(String text);
    }

    private final WindowSetup setup;
    private final Display display;
    private final Executor ui;
    private final RenderLoop renders;
    private final FrameRenderer renderer;
    private final SideJobs jobs;
    /** The file as read at the last save, and its last good scene, {@code file}, at the clock shown. */
    private ClockedScene source;
    private Scene file;
    private double clock;
    private boolean playing;
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
        this.renders = new RenderLoop(e -> ui.execute(() -> display.panel("rtd: internal error while rendering: " + e
                + ". This is a bug in rtd; please report it with the scene.")));
        this.renderer = new FrameRenderer(setup.engine(), setup.width(), setup.height(), setup.samples(),
                setup.threads());
        this.jobs = new SideJobs(ui);
        this.source = source;
        this.file = scene;
        this.clock = setup.clock();
        this.camera = new CameraController(scene.camera());
    }

    void start() {
        display.panel(Window.HELP);
        showSlider();
        render(FrameRenderer.STILL);
    }

    /** The scene with the window's camera. */
    Scene scene() {
        return new Scene(file.ambient(), camera.camera(), file.objects(), file.lights());
    }

    CameraController camera() {
        return camera;
    }

    FrameRenderer.Pass shown() {
        return shown;
    }

    double clock() {
        return clock;
    }

    boolean playing() {
        return playing;
    }

    /** Renders the scene as it is now in passes of {@code blocks}; one ending full cancels a render in progress. */
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

    private void status() {
        if (shown != null) {
            String clocked = source.file().usesClock() ? " · " + label(clock) : "";
            display.status(shown.status(setup.width(), setup.height(), underMouse,
                    (view == null ? "picture" : view.name()) + clocked));
        }
    }

    /** The clock as the status line and the slider's label write it: {@code clock 0.250}. */
    static String label(double clock) {
        return String.format(Locale.ROOT, "clock %.3f", clock);
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
        View[] views = View.values();
        show(view == null ? views[0] : view.ordinal() + 1 < views.length ? views[view.ordinal() + 1] : null);
    }

    /** A click on pixel (x, y): its explanation in the panel and its rays over the picture. */
    void select(int[] pixel) {
        if (pixel != null && pixel[1] < setup.height()) { // not outside the picture, nor on a view's legend
            selected = pixel;
            explainSelected();
        }
    }

    /** {@code Esc}: no pixel selected. */
    void deselect() {
        selected = null;
        display.rays(List.of());
        display.panel(Window.HELP);
    }

    private void explainSelected() {
        int[] pixel = selected;
        if (pixel != null) {
            jobs.explain(scene(), setup.scene(), pixel[0], pixel[1], setup.width(), setup.height(), (text, lines) -> {
                if (Arrays.equals(selected, pixel)) {
                    display.panel(text);
                    display.rays(lines);
                }
            });
        }
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
        } else {
            jobs.save(shown.picture(), setup.savedPicture(), display::panel);
        }
    }

    /** The file saved again: parsed at the clock shown, or its mistakes shown; the file's camera if it changed. */
    void reloaded(ClockedScene read) {
        source = read;
        Scene scene;
        try {
            scene = read.at(clock);
        } catch (SceneException e) {
            mistake(e.report(), "");
            return;
        }
        playing &= read.file().usesClock(); // known once the file is parsed
        showSlider();
        if (!sameCamera(scene.camera(), file.camera())) {
            camera = new CameraController(scene.camera()); // the file's new camera
        }
        file = scene;
        render(FrameRenderer.STILL);
        panelAgain();
    }

    /**
     * The slider moved to {@code to} by the user: playing stops (the slider is the user's now), and a frame at the
     * moving resolution follows while it is dragged ({@code dragging}), the full picture once it is let go.
     */
    void slid(double to, boolean dragging) {
        playing = false;
        atClock(to, !dragging);
    }

    /** {@code P}: plays the clock or pauses it; the paused clock's picture is drawn in full. */
    void play() {
        if (!source.file().usesClock()) {
            display.panel("The scene does not use clock: there is nothing to play.\n\n" + Window.HELP);
            return;
        }
        playing = !playing;
        if (!playing) {
            atClock(clock, true);
        }
        status();
    }

    /** The play timer's tick, {@code elapsedNanos} after the one before: the next frame, if playing. */
    void tick(long elapsedNanos) {
        if (playing) {
            atClock(next(clock, elapsedNanos), false);
        }
    }

    /** The played clock {@code elapsedNanos} after {@code clock}, wrapped into [0, 1). */
    static double next(double clock, long elapsedNanos) {
        double next = clock + (double) elapsedNanos / PASS_NANOS;
        return next - Math.floor(next);
    }

    /** The scene at clock {@code to}, in {@code full} or at the moving resolution; or its mistake at that clock. */
    void atClock(double to, boolean full) {
        clock = to;
        showSlider();
        Scene scene;
        try {
            scene = source.at(to);
        } catch (SceneException e) {
            mistake(e.report(), ", or move the clock");
            status();
            return;
        }
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

    private void showSlider() {
        display.clock(source.file().usesClock() ? clock : null);
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
            display.panel(Window.HELP);
        }
    }

    @Override
    public void close() {
        renders.close();
        jobs.close();
    }
}
