package rtd.io;

import java.util.Arrays;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.math.Vector3f;

/**
 * The values of the statement being read, group by group, where each was written, and the
 * rules they must follow (the scene file of Part I and its extension in Part II of the spec):
 * every number finite, a radius, zoom or scale above 0, a direction not zero, a colour channel a
 * whole number from 0 to 255, and so on. A statement's {@link Statement.Builder} asks for its
 * groups here by their index; a broken rule becomes an error at the value that breaks it, worded
 * with the group's meaning ("the x of the centre must be a finite number").
 *
 * <p>A reader reuses one for every line, so a line of numbers makes no object per number. An
 * object that names a material is built only when the whole file is read, from a {@link #copy}.
 */
final class GroupValues {

    private final SourceText source;
    private Statement statement;
    private int line;
    private int lineStart;

    /** The numbers (or, for a name, nothing) of all groups, where each stands, and a property's key. */
    private float[] values = new float[16];
    private int[] starts = new int[16];
    private int[] ends = new int[16];
    private int[] keys = new int[16];
    private int count;

    /** Per group: the index of its first value, and the offset of its '('. */
    private int[] firsts = new int[8];
    private int[] opens = new int[8];
    private int groupCount;

    private Material material = Material.DEFAULT;

    GroupValues(SourceText source) {
        this.source = source;
    }

    // ---- filled by the reader -----------------------------------------------------------

    /** Starts a statement on the line that starts at byte {@code lineStart}. */
    void begin(Statement statement, int line, int lineStart) {
        this.statement = statement;
        this.line = line;
        this.lineStart = lineStart;
        this.count = 0;
        this.groupCount = 0;
        this.material = Material.DEFAULT;
    }

    /** Starts the next group, whose '(' stands at {@code offset}. */
    void openGroup(int offset) {
        if (groupCount == firsts.length) {
            firsts = Arrays.copyOf(firsts, 2 * groupCount);
            opens = Arrays.copyOf(opens, 2 * groupCount);
        }
        firsts[groupCount] = count;
        opens[groupCount] = offset;
        groupCount++;
    }

    /** Keeps a number of the current group, written at {@code bytes[start, end)}. */
    void add(float value, int start, int end) {
        if (count == values.length) {
            grow();
        }
        values[count] = value;
        starts[count] = start;
        ends[count] = end;
        keys[count] = -1;
        count++;
    }

    /** Keeps the name or path of the current group, written at {@code bytes[start, end)}. */
    void addName(int start, int end) {
        add(Float.NaN, start, end);
    }

    /** Keeps {@code key=value} of the current group: the key's index among the group's keys. */
    void addProperty(int key, float value, int start, int end) {
        add(value, start, end);
        keys[count - 1] = key;
    }

    /** Whether group {@code g} has been opened and holds a value (a name, a number) yet. */
    boolean hasValue(int g) {
        return g < groupCount && (g + 1 < groupCount ? firsts[g + 1] : count) > firsts[g];
    }

    /** Whether the current group already holds the key with index {@code key}. */
    boolean lastHasKey(int key) {
        for (int i = firsts[groupCount - 1]; i < count; i++) {
            if (keys[i] == key) {
                return true;
            }
        }
        return false;
    }

    private void grow() {
        values = Arrays.copyOf(values, 2 * count);
        starts = Arrays.copyOf(starts, 2 * count);
        ends = Arrays.copyOf(ends, 2 * count);
        keys = Arrays.copyOf(keys, 2 * count);
    }

    /** An independent copy, for an object that is built when the whole file is read. */
    GroupValues copy() {
        GroupValues copy = new GroupValues(source);
        copy.statement = statement;
        copy.line = line;
        copy.lineStart = lineStart;
        copy.values = Arrays.copyOf(values, count);
        copy.starts = Arrays.copyOf(starts, count);
        copy.ends = Arrays.copyOf(ends, count);
        copy.keys = Arrays.copyOf(keys, count);
        copy.count = count;
        copy.firsts = Arrays.copyOf(firsts, groupCount);
        copy.opens = Arrays.copyOf(opens, groupCount);
        copy.groupCount = groupCount;
        return copy;
    }

    /** Sets the finish that {@link #material()} gives, once the material's name is known to mean it. */
    void useMaterial(Material material) {
        this.material = material;
    }

    // ---- asked for by the builders ------------------------------------------------------

    /** The statement these values belong to. */
    Statement statement() {
        return statement;
    }

    /** The number of the line the statement stands on. */
    int line() {
        return line;
    }

    /** The source the statement was read from. */
    SourceText source() {
        return source;
    }

    /** The finish of the object: the material its last group names, or {@link Material#DEFAULT}. */
    Material material() {
        return material;
    }

    /** The one number of group {@code g}, which must be finite. */
    float finite(int g) throws StatementError {
        return finite(firsts[g], meaning(g));
    }

    /** The one number of group {@code g}, which must be finite and greater than 0 (a radius, a zoom). */
    float positive(int g) throws StatementError {
        int i = firsts[g];
        float value = finite(i, meaning(g));
        if (value > 0) {
            return value;
        }
        throw errorAt(starts[i], "the " + meaning(g) + " must be greater than 0, found " + written(i), null);
    }

    /** The one number of group {@code g}, finite and strictly between {@code low} and {@code high}. */
    float between(int g, float low, float high, String unit, String help) throws StatementError {
        int i = firsts[g];
        float value = finite(i, meaning(g));
        if (value > low && value < high) {
            return value;
        }
        throw errorAt(starts[i], "the " + meaning(g) + " must be greater than " + number(low) + " and less than "
                + number(high) + " " + unit + ", found " + written(i), help);
    }

    /** The three numbers of group {@code g} as a vector of finite numbers. */
    Vector3f vector(int g) throws StatementError {
        int i = firsts[g];
        for (int k = 0; k < 3; k++) {
            if (!Float.isFinite(values[i + k])) {
                finite(i + k, "xyz".charAt(k) + " of the " + meaning(g));
            }
        }
        return new Vector3f(values[i], values[i + 1], values[i + 2]);
    }

    /**
     * The three numbers of group {@code g} as a direction: finite, not zero, and neither too short
     * nor too long to compute with in float (a view direction, a plane's normal).
     */
    Vector3f direction(int g, String zeroHelp) throws StatementError {
        Vector3f direction = vector(g);
        int i = firsts[g];
        if (direction.x() == 0 && direction.y() == 0 && direction.z() == 0) {
            throw errorAt(starts[i], "the " + meaning(g) + " must not be zero, found " + groupText(g), zeroHelp);
        }
        float squaredLength = direction.dot(direction);
        if (!(squaredLength >= Float.MIN_NORMAL) || Float.isInfinite(squaredLength)) {
            throw errorAt(starts[i], "the " + meaning(g) + " " + groupText(g) + " is too "
                    + (Float.isInfinite(squaredLength) ? "long" : "short") + " to compute with in float",
                    "only its direction matters: scale it to a length near 1");
        }
        return direction;
    }

    /** The three numbers of group {@code g}: a colour, each channel a whole number from 0 to 255. */
    Color colour(int g) throws StatementError {
        int i = firsts[g];
        return new Color(channel(i, "red"), channel(i + 1, "green"), channel(i + 2, "blue"));
    }

    /** The name or path that group {@code g} holds, as written. */
    String name(int g) {
        int i = firsts[g];
        return source.text(starts[i], ends[i]);
    }

    /**
     * The value of {@code key} in the properties of group {@code g}, or {@code fallback} if the
     * group does not give it; a given value must be finite and at least {@code minimum}.
     */
    float property(int g, String key, float fallback, float minimum) throws StatementError {
        int index = statement.groups().get(g).keys().indexOf(key);
        int end = g + 1 < groupCount ? firsts[g + 1] : count;
        for (int i = firsts[g]; i < end; i++) {
            if (keys[i] == index) {
                String name = "value of '" + key + "'";
                float value = finite(i, name);
                if (value >= minimum) {
                    return value;
                }
                throw errorAt(starts[i], "the " + name + " must be at least " + number(minimum) + ", found " + written(i),
                        minimum > 0 ? "an index of refraction is 1 for air, 1.33 for water, 1.5 for glass"
                                : "0 turns this part of the finish off");
            }
        }
        return fallback;
    }

    /** The number {@code k} of group {@code g} as written, for messages. */
    String written(int g, int k) {
        return written(firsts[g] + k);
    }

    /** An error at the '(' of group {@code g}. */
    StatementError errorAtGroup(int g, String message, String help) {
        return errorAt(opens[g], message, help);
    }

    /** An error at number {@code k} of group {@code g}, or at the name of a name group ({@code k = 0}). */
    StatementError errorAtValue(int g, int k, String message, String help) {
        return errorAt(starts[firsts[g] + k], message, help);
    }

    /** Where value {@code k} of group {@code g} stands, as an error with no message yet. */
    SceneError placeOfValue(int g, int k) {
        return errorAtValue(g, k, "", null).place();
    }

    /** An error at byte {@code offset} of the statement's line. */
    StatementError errorAt(int offset, String message, String help) {
        return new StatementError(new SceneError(source.name(), line, source.column(lineStart, offset), message,
                source.lineText(lineStart), help));
    }

    // ---- the rules --------------------------------------------------------------------------

    /** Number {@code i}, which must be finite (not NaN, not infinite, not beyond a float's range). */
    private float finite(int i, String name) throws StatementError {
        float value = values[i];
        if (Float.isFinite(value)) {
            return value;
        }
        String written = written(i);
        boolean overflow = !written.contains("NaN") && !written.contains("Infinity");
        throw errorAt(starts[i], "the " + name + " must be a finite number, found " + written
                + (overflow ? ", which is too large for a float" : ""),
                overflow ? "a float holds numbers up to about 3.4e38" : null);
    }

    private int channel(int i, String name) throws StatementError {
        float value = values[i];
        if (!(value >= 0 && value <= 255 && value == Math.rint(value))) {
            throw errorAt(starts[i], "the " + name + " channel must be a whole number from 0 to 255, found "
                    + written(i), null);
        }
        return (int) value;
    }

    private String meaning(int g) {
        return g < statement.groups().size() ? statement.groups().get(g).meaning() : Statement.MATERIAL.meaning();
    }

    private String written(int i) {
        return source.text(starts[i], ends[i]);
    }

    private String groupText(int g) {
        int end = g + 1 < groupCount ? firsts[g + 1] : count;
        StringBuilder text = new StringBuilder("(");
        for (int i = firsts[g]; i < end; i++) {
            text.append(i > firsts[g] ? "|" : "").append(written(i));
        }
        return text.append(')').toString();
    }

    /** 180 rather than 180.0 in a message. */
    private static String number(float value) {
        return value == Math.rint(value) ? String.valueOf((long) value) : String.valueOf(value);
    }
}
