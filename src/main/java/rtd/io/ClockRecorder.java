package rtd.io;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import rtd.scene.Scene;

/**
 * Notes, while a scene is read for {@link SceneFile#withClock}, which numbers of each statement use the clock:
 * the {@link ClockedScene}'s table in the making. {@link SceneContents} tells it what each statement made; a
 * statement none of whose numbers uses the clock leaves no trace.
 */
final class ClockRecorder {

    private ClockFields ambient = ClockFields.NONE;
    private ClockFields camera = ClockFields.NONE;
    private final Map<Object, ClockFields> parts = new IdentityHashMap<>();
    private final List<String> unwritten = new ArrayList<>();

    /** The statement of {@code v} made {@code part}, an object or a point light. */
    void part(Object part, StatementValues v) {
        ClockFields fields = ClockFields.of(v);
        if (!fields.isEmpty()) {
            parts.put(part, fields);
        }
    }

    /** The statement of {@code v} is the scene's {@code ambient} (a second is a mistake: that scene is never made). */
    void ambient(StatementValues v) {
        ambient = ClockFields.of(v);
    }

    /** The statement of {@code v} made the scene's camera (a second is a mistake: that scene is never made). */
    void camera(StatementValues v) {
        camera = ClockFields.of(v);
    }

    /** The statement of {@code v} made something whose numbers the table does not carry. */
    void unwritten(StatementValues v) {
        if (ClockFields.of(v).isEmpty()) {
            return;
        }
        String statement = "the '" + v.statement().keyword() + "' at line " + v.line();
        if (!unwritten.contains(statement)) { // an area light makes many lights
            unwritten.add(statement);
        }
    }

    /** The table for {@code scene}, the scene that was read. */
    ClockedScene scene(Scene scene) {
        return new ClockedScene(scene, ambient, camera, parts, unwritten);
    }
}
