package rtd.window;

import java.util.Locale;
import rtd.io.SceneException;
import rtd.scene.Scene;
import rtd.window.WindowSetup.ClockedScene;

/**
 * The window's clock: the scene file as read last, parsed again at the clock slider's value or the play key's, each
 * scene handed to its {@link WindowSession}; a value that breaks at a clock (a radius negative at clock = 0.75) is
 * shown as a saved mistake is, and the last good picture stays. The play key runs the clock from where it is towards 1
 * and wraps round to 0, one pass in {@link #PASS_NANOS}, as the frames of an animation loop: time, not frames, moves
 * it, so a slow scene plays at the same pace in fewer frames. Used on the window's thread only.
 */
final class ClockControl {

    /** One pass of the played clock from 0 to 1: 5 seconds. */
    static final long PASS_NANOS = 5_000_000_000L;
    /** How often the window asks for the next frame while playing: 25 times a second at most. */
    static final int TICK_MILLIS = 40;

    private final WindowSession session;
    private final Display display;
    private ClockedScene source;
    private double clock;
    private boolean playing;

    /** The clock at {@code clock} of {@code source}, whose scenes go to {@code session}, its slider to {@code display}. */
    ClockControl(WindowSession session, Display display, ClockedScene source, double clock) {
        this.session = session;
        this.display = display;
        this.source = source;
        this.clock = clock;
    }

    double clock() {
        return clock;
    }

    boolean playing() {
        return playing;
    }

    /** Shows the slider at the clock, or hides it for a scene that does not use {@code clock}. */
    void showSlider() {
        display.clock(source.file().usesClock() ? clock : null);
    }

    /** The status line's part for the clock, {@code " · clock 0.250"}, or nothing for a scene without one. */
    String status() {
        return source.file().usesClock() ? " · " + label(clock) : "";
    }

    /** The clock as the status line and the slider's label write it: {@code clock 0.250}. */
    static String label(double clock) {
        return String.format(Locale.ROOT, "clock %.3f", clock);
    }

    /**
     * The file saved again ({@code read}), parsed at the clock shown, its slider shown again; a scene without the clock
     * does not play.
     */
    Scene read(ClockedScene read) throws SceneException {
        source = read;
        Scene scene = read.at(clock);
        playing &= read.file().usesClock();
        showSlider();
        return scene;
    }

    /**
     * The user moved the slider to {@code to}: playing stops (the slider is the user's now), and a frame at the moving
     * resolution follows while it is dragged ({@code dragging}), the full picture once it is let go.
     */
    void slid(double to, boolean dragging) {
        playing = false;
        if (dragging) {
            moved(to);
        } else {
            rested(to);
        }
    }

    /** The clock dragged or played to {@code to}: a frame at the moving resolution. */
    void moved(double to) {
        showAt(to, false);
    }

    /** The clock at rest at {@code to}: the full picture. */
    void rested(double to) {
        showAt(to, true);
    }

    /** {@code P}: plays the clock or pauses it; the paused clock's picture is drawn in full. */
    void play() {
        if (!source.file().usesClock()) {
            display.panel("The scene does not use clock: there is nothing to play.\n\n" + SceneWindow.HELP);
            return;
        }
        playing = !playing;
        if (!playing) {
            rested(clock);
        }
        session.status();
    }

    /** The play timer's tick, {@code elapsedNanos} after the one before: the next frame, if playing. */
    void tick(long elapsedNanos) {
        if (playing) {
            moved(next(clock, elapsedNanos));
        }
    }

    /** The played clock {@code elapsedNanos} after {@code clock}, wrapped into [0, 1). */
    static double next(double clock, long elapsedNanos) {
        double next = clock + (double) elapsedNanos / PASS_NANOS;
        return next - Math.floor(next);
    }

    /** The scene at {@code to} to the session, in full or at the moving resolution; or its mistake, at that clock. */
    private void showAt(double to, boolean full) {
        clock = to;
        showSlider();
        try {
            session.atClock(source.at(to), full);
        } catch (SceneException e) {
            session.mistake(e.report(), ", or move the clock");
            session.status();
        }
    }
}
