package rtd.io;

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
 * <p>{@link #unwritten} lists the statements whose clock the table does not carry (a material, a pattern,
 * a transformation, a mesh or an area light that uses the clock): a scene with any is to be written frame by
 * frame.
 */
public final class ClockedScene {

    private final Scene scene;
    private final ClockFields ambient;
    private final ClockFields camera;
    private final Map<Object, ClockFields> parts;
    private final List<String> unwritten;

    ClockedScene(Scene scene, ClockFields ambient, ClockFields camera, Map<Object, ClockFields> parts,
            List<String> unwritten) {
        this.scene = scene;
        this.ambient = ambient;
        this.camera = camera;
        this.parts = Collections.unmodifiableMap(new IdentityHashMap<>(parts));
        this.unwritten = List.copyOf(unwritten);
    }

    /** The scene at the clock it was read at. */
    public Scene scene() {
        return scene;
    }

    /**
     * The same table beside {@code other}, a scene with the same objects and lights, such as this one at another
     * size (its orthographic camera's zoom scaled).
     */
    public ClockedScene with(Scene other) {
        return new ClockedScene(other, ambient, camera, parts, unwritten);
    }

    /** The {@code ambient} statement's numbers that use the clock. */
    public ClockFields ambient() {
        return ambient;
    }

    /** The camera statement's numbers that use the clock. */
    public ClockFields camera() {
        return camera;
    }

    /** The numbers that use the clock of the statement that made {@code part}, one of the scene's objects or lights. */
    public ClockFields of(Object part) {
        return parts.getOrDefault(part, ClockFields.NONE);
    }

    /** Whether any number of the scene uses the clock. */
    public boolean usesClock() {
        return !ambient.isEmpty() || !camera.isEmpty() || !parts.isEmpty() || !unwritten.isEmpty();
    }

    /** The statements that use the clock where the table does not carry it, such as "the 'material' at line 4". */
    public List<String> unwritten() {
        return unwritten;
    }
}
