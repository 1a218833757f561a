package rtd.window;

import rtd.io.SceneException;
import rtd.scene.Scene;

/**
 * The window's clock: the scene file as read last, parsed again at the clock slider's value or the play key's
 * ({@link ClockPlay}), each scene handed to its {@link WindowSession}; a value that breaks at a clock (a radius
 * negative at clock = 0.75) is shown as a saved mistake is, and the last good picture stays. Used on the window's
 * thread only.
 */
final class ClockControl {

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

    /** The clock shown. */
    double clock() {
        return clock;
    }

    /** Whether {@code P} plays the clock now. */
    boolean playing() {
        return playing;
    }

    /** The slider's value, or null for no slider: the scene does not use {@code clock}. */
    Double slider() {
        return source.usesClock() ? clock : null;
    }

    /** The status line's part for the clock, {@code " · clock 0.250"}, or nothing for a scene without one. */
    String status() {
        return source.usesClock() ? " · " + StatusText.clock(clock) : "";
    }

    /** The file saved again ({@code read}), parsed at the clock shown; a scene without the clock does not play. */
    Scene read(ClockedScene read) throws SceneException {
        source = read;
        Scene scene = read.at(clock);
        playing &= read.usesClock();
        return scene;
    }

    /**
     * The user moved the slider to {@code to}: playing stops (the slider is the user's now), and a frame at the
     * moving resolution follows while it is dragged ({@code dragging}), the full picture once it is let go.
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
        Scene scene = at(to);
        if (scene != null) {
            session.atClock(scene, false);
        }
    }

    /** The clock at rest at {@code to}: the full picture. */
    void rested(double to) {
        Scene scene = at(to);
        if (scene != null) {
            session.atClock(scene, true);
        }
    }

    /** {@code P}: plays the clock or pauses it; the paused clock's picture is drawn in full. */
    void play() {
        if (!source.usesClock()) {
            display.panel("The scene does not use clock: there is nothing to play.\n\n" + Keys.HELP);
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
            moved(ClockPlay.next(clock, elapsedNanos));
        }
    }

    /** The scene at {@code to}, or null with its mistake shown (the status line says the clock). */
    private Scene at(double to) {
        clock = to;
        display.clock(slider());
        try {
            return source.at(to);
        } catch (SceneException e) {
            session.mistake(e.report(), ", or move the clock");
            session.status();
            return null;
        }
    }
}
