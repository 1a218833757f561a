package rtd.io;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import rtd.scene.Scene;

/**
 * A scene read at one clock together with the expressions of its numbers that use the clock (Part III,
 * "Expressions, named values and the clock"), so that an animation can be written as one POV-Ray file whose
 * numbers follow POV-Ray's {@code clock}. The expressions stand beside the scene, in a table from each of its
 * objects and lights (by identity) to its {@link ClockFields}: the shapes themselves hold numbers only.
 *
 * @param scene     the scene at the clock it was read at
 * @param ambient   the {@code ambient} statement's numbers that use the clock
 * @param camera    the camera statement's numbers that use the clock
 * @param parts     each object's and light's numbers that use the clock, by identity
 * @param unwritten the statements whose clock the table does not carry (a material, a pattern, a
 *                  transformation, a mesh or an area light that uses the clock, "the 'material' at line 4"): a
 *                  scene with any is to be written frame by frame
 */
public record ClockedScene(Scene scene, ClockFields ambient, ClockFields camera, Map<Object, ClockFields> parts,
        List<String> unwritten) {

    public ClockedScene {
        parts = Collections.unmodifiableMap(new IdentityHashMap<>(parts));
        unwritten = List.copyOf(unwritten);
    }

    /** The same table beside {@code other}, a scene with the same objects and lights, such as this one resized. */
    public ClockedScene with(Scene other) {
        return new ClockedScene(other, ambient, camera, parts, unwritten);
    }

    /** The numbers that use the clock of the statement that made {@code part}, one of the scene's objects or lights. */
    public ClockFields of(Object part) {
        return parts.getOrDefault(part, ClockFields.NONE);
    }

    public boolean usesClock() {
        return !ambient.isEmpty() || !camera.isEmpty() || !parts.isEmpty() || !unwritten.isEmpty();
    }

    /**
     * This table in the making: notes, while a scene is read, which numbers of each statement use the clock.
     * {@link SceneContents} tells it what each statement made; a statement none of whose numbers uses the
     * clock leaves no trace. A second {@code ambient} or camera is a mistake: that scene is never made.
     */
    static final class Recorder {

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

        void ambient(StatementValues v) {
            ambient = ClockFields.of(v);
        }

        void camera(StatementValues v) {
            camera = ClockFields.of(v);
        }

        /** The statement of {@code v} made something whose numbers the table does not carry. */
        void unwritten(StatementValues v) {
            String statement = "the '" + v.statement().keyword() + "' at line " + v.line();
            if (!ClockFields.of(v).isEmpty() && !unwritten.contains(statement)) { // an area light makes many lights
                unwritten.add(statement);
            }
        }

        /** The table for {@code scene}, the scene that was read. */
        ClockedScene scene(Scene scene) {
            return new ClockedScene(scene, ambient, camera, parts, unwritten);
        }
    }
}
