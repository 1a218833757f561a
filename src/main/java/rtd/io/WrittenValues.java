package rtd.io;

import java.util.Arrays;
import rtd.geometry.Material;

/**
 * The values of the statement being read as they are written, group by group, and where each
 * stands: the numbers (or, for a name or a path, where it is written) and a property's key.
 * {@link GroupReader} fills them number by number; {@link GroupValues}, the one kind of it, adds
 * the rules they must follow and is what a statement's {@link Statement.Builder} asks.
 *
 * <p>A reader reuses one for every line, so a line of numbers makes no object per number. An
 * object that names a material is built only when the whole file is read, from a
 * {@link GroupValues#copy}. The fields are not private because {@link GroupValues} reads them
 * as its own.
 */
abstract sealed class WrittenValues permits GroupValues {

    final SourceText source;
    Statement statement;
    int line;
    int lineStart;

    /** The numbers (or, for a name, nothing) of all groups, where each stands, and a property's key. */
    float[] values;
    int[] starts;
    int[] ends;
    int[] keys;
    int count;

    /** Per group: the index of its first value, and the offset of its '('. */
    int[] firsts;
    int[] opens;
    int groupCount;

    Material material = Material.DEFAULT;

    /** Room for {@code numbers} values and {@code groups} groups, which grows as the reader needs. */
    WrittenValues(SourceText source, int numbers, int groups) {
        this.source = source;
        values = new float[numbers];
        starts = new int[numbers];
        ends = new int[numbers];
        keys = new int[numbers];
        firsts = new int[groups];
        opens = new int[groups];
    }

    // ---- filled by the reader -----------------------------------------------------------

    /** Starts a statement on the line that starts at byte {@code lineStart}. */
    final void begin(Statement statement, int line, int lineStart) {
        this.statement = statement;
        this.line = line;
        this.lineStart = lineStart;
        this.count = 0;
        this.groupCount = 0;
        this.material = Material.DEFAULT;
    }

    /** Starts the next group, whose '(' stands at {@code offset}. */
    final void openGroup(int offset) {
        if (groupCount == firsts.length) {
            firsts = Arrays.copyOf(firsts, 2 * groupCount);
            opens = Arrays.copyOf(opens, 2 * groupCount);
        }
        firsts[groupCount] = count;
        opens[groupCount] = offset;
        groupCount++;
    }

    /** Keeps a number of the current group, written at {@code bytes[start, end)}. */
    final void add(float value, int start, int end) {
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
    final void addName(int start, int end) {
        add(Float.NaN, start, end);
    }

    /** Keeps {@code key=value} of the current group: the key's index among the group's keys. */
    final void addProperty(int key, float value, int start, int end) {
        add(value, start, end);
        keys[count - 1] = key;
    }

    /** Whether group {@code g} has been opened and holds a value (a name, a number) yet. */
    final boolean hasValue(int g) {
        return g < groupCount && (g + 1 < groupCount ? firsts[g + 1] : count) > firsts[g];
    }

    /** Whether the current group already holds the key with index {@code key}. */
    final boolean lastHasKey(int key) {
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

    /** Sets the finish that {@link #material()} gives, once the material's name is known to mean it. */
    final void useMaterial(Material material) {
        this.material = material;
    }

    // ---- asked for by the builders and their rules ---------------------------------------

    /** The statement these values belong to. */
    final Statement statement() {
        return statement;
    }

    /** The number of the line the statement stands on. */
    final int line() {
        return line;
    }

    /** The source the statement was read from. */
    final SourceText source() {
        return source;
    }

    /** The finish of the object: the material its last group names, or {@link Material#DEFAULT}. */
    final Material material() {
        return material;
    }

    /** The name or path that group {@code g} holds, as written. */
    final String name(int g) {
        int i = firsts[g];
        return source.text(starts[i], ends[i]);
    }

    /** The number {@code k} of group {@code g} as written, for messages. */
    final String written(int g, int k) {
        return written(firsts[g] + k);
    }

    /** An error at the '(' of group {@code g}. */
    final StatementError errorAtGroup(int g, String message, String help) {
        return errorAt(opens[g], message, help);
    }

    /** An error at number {@code k} of group {@code g}, or at the name of a name group ({@code k = 0}). */
    final StatementError errorAtValue(int g, int k, String message, String help) {
        return errorAt(starts[firsts[g] + k], message, help);
    }

    /** Where value {@code k} of group {@code g} stands, as an error with no message yet. */
    final SceneError placeOfValue(int g, int k) {
        return errorAtValue(g, k, "", null).place();
    }

    /** An error at byte {@code offset} of the statement's line. */
    final StatementError errorAt(int offset, String message, String help) {
        return new StatementError(new SceneError(source.name(), line, source.column(lineStart, offset), message,
                source.lineText(lineStart), help));
    }

    /** Value {@code i} (of all groups) as written, for messages. */
    final String written(int i) {
        return source.text(starts[i], ends[i]);
    }
}
