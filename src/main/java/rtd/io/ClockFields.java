package rtd.io;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * The numbers of one statement that use the clock (Part III, "Expressions, named values and the clock"), each
 * as the expression written, found by its group's meaning as the {@link Grammar} names it and its place in the
 * group: {@code of("centre", 1)} is the y of a sphere's centre. Every other number of the statement is the same
 * at every clock. The POV-Ray export writes these numbers with POV-Ray's own {@code clock}.
 */
public final class ClockFields {

    /** A statement none of whose numbers uses the clock. */
    public static final ClockFields NONE = new ClockFields(Map.of(), Map.of());

    /** Group meaning → its numbers' expressions, null where a number does not use the clock. */
    private final Map<String, Expression[]> clocked;
    /** Group meaning → its numbers as read at the clock of the reading, for every group of the statement. */
    private final Map<String, float[]> values;

    private ClockFields(Map<String, Expression[]> clocked, Map<String, float[]> values) {
        this.clocked = clocked;
        this.values = values;
    }

    /** The numbers of {@code v}'s statement that use the clock; {@link #NONE} if none does. */
    static ClockFields of(StatementValues v) {
        if (!v.anyExpression()) {
            return NONE;
        }
        Map<String, Expression[]> found = new HashMap<>();
        Map<String, float[]> numbers = new HashMap<>();
        for (int g = 0; g < v.groupCount(); g++) {
            int size = v.size(g);
            String key = v.meaning(g);
            for (int n = 2; numbers.containsKey(key); n++) { // a meaning that repeats (a transform's steps): "step 2"
                key = v.meaning(g) + " " + n;
            }
            numbers.put(key, v.numbers(g));
            for (int k = 0; k < size; k++) {
                Expression tree = v.tree(g, k);
                if (tree != null && tree.usesClock()) {
                    found.computeIfAbsent(key, meaning -> new Expression[size])[k] = tree;
                }
            }
        }
        return found.isEmpty() ? NONE : new ClockFields(Map.copyOf(found), Map.copyOf(numbers));
    }

    /** Number {@code k} of the group that means {@code group} if it uses the clock, else null. */
    public Expression of(String group, int k) {
        Expression[] numbers = clocked.get(group);
        return numbers == null || k >= numbers.length ? null : numbers[k];
    }

    /** Number {@code k} of the group that means {@code group} as read at the reading's clock (NaN if there is none). */
    public float value(String group, int k) {
        float[] numbers = values.get(group);
        return numbers == null || k >= numbers.length ? Float.NaN : numbers[k];
    }

    /** Whether a number of the group that means {@code group} uses the clock. */
    public boolean has(String group) {
        return clocked.containsKey(group);
    }

    /** The meanings of the groups with a number that uses the clock. */
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
