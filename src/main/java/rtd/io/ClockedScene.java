package rtd.io;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import rtd.scene.Scene;
import rtd.scene.SceneWarnings;

/**
 * A scene read at one clock beside the expressions of its numbers that use the clock (Part III, "Expressions,
 * named values and the clock"), so that an animation can be one POV-Ray file that follows POV-Ray's {@code clock}.
 *
 * @param parts     each object's and light's numbers that use the clock, by identity
 * @param unwritten the statements that use the clock where the table cannot say ("the 'material' at line 4"): a
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

    /**
     * The numbers of one statement that use the clock, found by its group's meaning in the {@link Grammar} and
     * its place in the group: {@code of("centre", 1)} is the y of a sphere's centre.
     *
     * @param clocked group meaning → its numbers' expressions, null where a number does not use the clock
     * @param values  group meaning → its numbers as read at the reading's clock, for every group (never changed)
     */
    public record ClockFields(Map<String, Expression[]> clocked, Map<String, float[]> values) {

        public static final ClockFields NONE = new ClockFields(Map.of(), Map.of());

        static ClockFields of(StatementValues v) {
            if (!v.anyExpression()) {
                return NONE;
            }
            Map<String, Expression[]> found = new HashMap<>();
            Map<String, float[]> numbers = new HashMap<>();
            for (int g = 0; g < v.groupCount(); g++) {
                int size = v.size(g);
                String meaning = v.statement().group(g).meaning();
                String key = meaning;
                for (int n = 2; numbers.containsKey(key); n++) { // a repeated meaning (a transform's steps): "step 2"
                    key = meaning + " " + n;
                }
                numbers.put(key, v.numbers(g));
                for (int k = 0; k < size; k++) {
                    Expression tree = v.tree(g, k);
                    if (tree != null && tree.usesClock()) {
                        found.computeIfAbsent(key, group -> new Expression[size])[k] = tree;
                    }
                }
            }
            return found.isEmpty() ? NONE : new ClockFields(Map.copyOf(found), Map.copyOf(numbers));
        }

        /** Number {@code k} of {@code group} if it uses the clock, else null. */
        public Expression of(String group, int k) {
            Expression[] numbers = clocked.get(group);
            return numbers == null || k >= numbers.length ? null : numbers[k];
        }

        /** Number {@code k} of {@code group} as read (NaN if there is none). */
        public float value(String group, int k) {
            float[] numbers = values.get(group);
            return numbers == null || k >= numbers.length ? Float.NaN : numbers[k];
        }

        public Set<String> groups() {
            return clocked.keySet();
        }

        /** Every number's expression that uses the clock, in no particular order. */
        public List<Expression> expressions() {
            return clocked.values().stream().flatMap(Arrays::stream).filter(Objects::nonNull).toList();
        }

        public boolean isEmpty() {
            return clocked.isEmpty();
        }
    }

    /** This table in the making, told by {@link SceneContents} what each statement made. */
    static final class Recorder {

        private ClockFields ambient = ClockFields.NONE;
        private ClockFields camera = ClockFields.NONE;
        private final Map<Object, ClockFields> parts = new IdentityHashMap<>();
        private final List<String> unwritten = new ArrayList<>();

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

        ClockedScene scene(Scene scene) {
            return new ClockedScene(scene, ambient, camera, parts, unwritten);
        }
    }

    /** An expression as written, its value, and the clock if it uses it: "1-2*clock, which is -0.5 at clock = 0.75". */
    static String withValue(String text, float value, boolean usesClock, double clock) {
        String number = value == Math.rint(value) && Math.abs(value) < 1e9 ? String.valueOf((long) value)
                : String.valueOf(value);
        return text + ", which is " + number + (usesClock ? " at clock = " + SceneWarnings.number(clock) : "");
    }
}
