package rtd.window;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.Executor;
import rtd.camera.ICamera;
import rtd.io.SceneException;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.view.View;
import rtd.window.WindowSetup.ClockedScene;

/**
 * What the window does, without its Swing parts: the scene file at the clock shown, the camera as the mouse moved it,
 * the view, and the renders; the panel of text is its {@link SidePanel}'s. It lives on the window's thread (Swing's
 * event thread, {@code ui}); renders run on the {@link FrameRenderer}'s thread, and what they find comes back through
 * {@code ui} to the {@link Display}.
 *
 * <p>The clock slider and {@code P} parse the file read at the last save again at each clock; a value broken at a clock
 * (a radius negative at clock = 0.75) shows as a saved mistake does, and the last good picture stays. Playing runs
 * the clock up to 1 and then from 0 again, one pass in {@link #PASS_NANOS}: time, not frames, moves it, so a slow scene
 * plays at the same pace in fewer frames. A camera the user has not moved follows the file's at each clock.
 */
final class WindowSession implements AutoCloseable {

    /** One pass of the played clock from 0 to 1: 5 seconds. */
    static final long PASS_NANOS = 5_000_000_000L;

    private final WindowSetup setup;
    private final Display display;
    private final Executor ui;
    private final FrameRenderer renderer;
    private final SidePanel panel;
    /** The file as read at the last save, and its last good scene, {@code file}, at the clock shown. */
    private ClockedScene source;
    private Scene file;
    private double clock;
    private boolean playing;
    private CameraController camera;
    private View view;
    private int[] underMouse;
    private FrameRenderer.Pass shown;
    /** Whether the panel is to show the view's scale once its full picture is drawn. */
    private boolean legendWanted;

    /** A session on {@code scene}, which is {@code source} parsed at {@code setup}'s clock. */
    WindowSession(WindowSetup setup, ClockedScene source, Scene scene, Display display, Executor ui) {
        this.setup = setup;
        this.display = display;
        this.ui = ui;
        this.renderer = new FrameRenderer(setup, ui, this::show, e -> ui.execute(() -> display.panel("rtd: internal "
                + "error while rendering: " + e + ". This is a bug in rtd; please report it with the scene.")));
        this.panel = new SidePanel(setup, display, ui);
        this.source = source;
        this.file = scene;
        this.clock = setup.clock();
        this.camera = new CameraController(scene.camera());
    }

    void start() {
        display.panel(SidePanel.HELP);
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

    /** Renders the scene as it is now in passes of {@code blocks}, or a moving frame for null. */
    private void render(List<Integer> blocks) {
        renderer.frame(file, camera.camera(), view, blocks);
    }

    private void show(FrameRenderer.Pass pass, boolean newest) {
        shown = pass;
        if (legendWanted && pass.block() == 1 && newest && !panel.selected()) {
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
        render(null);
    }

    /** The mouse rests after moving the camera: the full picture, and the selected pixel's rays again. */
    void rested() {
        render(FrameRenderer.RESTED);
        panel.explain(scene());
    }

    /** {@code R}: the file's camera at the clock shown. */
    void resetCamera() {
        camera = new CameraController(file.camera());
        render(FrameRenderer.STILL);
        panel.explain(scene());
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
        panel.select(pixel, scene());
    }

    /** {@code Esc}: no pixel selected. */
    void deselect() {
        panel.deselect();
    }

    /** {@code C}: the camera as a scene line, on the clipboard and in the panel. */
    void copyCamera() {
        panel.copy(camera.camera());
    }

    /** {@code Ctrl+S}: the full picture (or view) as shown, written as {@code -o} writes, beside the scene. */
    void save() {
        panel.save(shown, renderer.newest());
    }

    /** The file saved again: parsed at the clock shown, or its mistakes shown; the file's camera if it changed. */
    void reloaded(ClockedScene read) {
        source = read;
        Scene scene;
        try {
            scene = read.at(clock);
        } catch (SceneException e) {
            panel.mistake(e.report(), "");
            return;
        }
        playing &= read.file().usesClock(); // known once the file is parsed
        showSlider();
        if (!sameCamera(scene.camera(), file.camera())) {
            camera = new CameraController(scene.camera()); // the file's new camera
        }
        file = scene;
        render(FrameRenderer.STILL);
        panel.fixed(scene(), true);
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
            display.panel("The scene does not use clock: there is nothing to play.\n\n" + SidePanel.HELP);
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
            panel.mistake(e.report(), ", or move the clock");
            status();
            return;
        }
        if (sameCamera(camera.camera(), file.camera())) {
            camera = new CameraController(scene.camera()); // not moved by the user: it follows the file's
        }
        file = scene;
        panel.fixed(scene(), false);
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
        panel.mistake(report, orClock);
    }

    @Override
    public void close() {
        renderer.close();
        panel.close();
    }
}
