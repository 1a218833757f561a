package rtd.io;

import java.util.Arrays;

/**
 * What the {@link GroupReader} found in the groups of one statement, and where: each value, its offsets and
 * its key's index, and each group's first value and '('. One is filled for every line, so that a line of
 * numbers makes no object per number. It is the storage of {@link StatementValues}, which alone reads it:
 * builders see a value only through the rule it must follow.
 */
final class WrittenGroups {

    float[] values;
    int[] starts;
    int[] ends;
    /** The index of a property's key among its group's keys, or −1. */
    int[] keys;
    /** For a value written as an expression (Part III): its tree and its value in double precision; else null. */
    Expression[] trees;
    double[] exact;
    /** Whether a value of this statement is an expression. */
    boolean anyExpression;
    int count;
    int[] firsts;
    int[] opens;
    int groupCount;
    /** The group written {@code (at x|y|z)}, a point to look at, or −1. */
    int target = -1;
    /** The group that holds a name where numbers may stand (an object's colour naming a pattern), or −1. */
    int named = -1;

    /** Room for {@code values} values and {@code groups} groups, which grows as the reader needs. */
    WrittenGroups(int values, int groups) {
        this.values = new float[values];
        starts = new int[values];
        ends = new int[values];
        keys = new int[values];
        trees = new Expression[values];
        exact = new double[values];
        firsts = new int[groups];
        opens = new int[groups];
    }

    /** Forgets the groups of the last statement. */
    void clear() {
        if (anyExpression) { // only then does a tree need forgetting: a plain number's stays null
            Arrays.fill(trees, 0, count, null);
            anyExpression = false;
        }
        count = 0;
        groupCount = 0;
        target = -1;
        named = -1;
    }

    /** Starts the next group, whose '(' stands at {@code offset}. */
    void openGroup(int offset) {
        if (groupCount == firsts.length) {
            firsts = Arrays.copyOf(firsts, 2 * groupCount);
            opens = Arrays.copyOf(opens, 2 * groupCount);
        }
        firsts[groupCount] = count;
        opens[groupCount++] = offset;
    }

    /** Marks the current group as written {@code (at x|y|z)}. */
    void markTarget() {
        target = groupCount - 1;
    }

    /** Marks the current group as holding a name in the place of its numbers. */
    void markNamed() {
        named = groupCount - 1;
    }

    /** Keeps a number of the current group, written at {@code bytes[start, end)}; a name or path is NaN. */
    void add(float value, int start, int end) {
        if (count == values.length) {
            values = Arrays.copyOf(values, 2 * count);
            starts = Arrays.copyOf(starts, 2 * count);
            ends = Arrays.copyOf(ends, 2 * count);
            keys = Arrays.copyOf(keys, 2 * count);
            trees = Arrays.copyOf(trees, 2 * count);
            exact = Arrays.copyOf(exact, 2 * count);
        }
        values[count] = value;
        starts[count] = start;
        ends[count] = end;
        keys[count++] = -1;
    }

    /** Marks the value kept last as written as the expression {@code tree}, whose value is {@code exactValue}. */
    void markExpression(double exactValue, Expression tree) {
        trees[count - 1] = tree;
        exact[count - 1] = exactValue;
        anyExpression = true;
    }

    /** Keeps {@code key=value} of the current group: the key's index among the group's keys. */
    void addProperty(int key, float value, int start, int end) {
        add(value, start, end);
        keys[count - 1] = key;
    }

    /** Whether group {@code g} has been opened and holds a value (a name, a number) yet. */
    boolean hasValue(int g) {
        return g < groupCount && end(g) > firsts[g];
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

    /** The index after the last value of group {@code g}. */
    int end(int g) {
        return g + 1 < groupCount ? firsts[g + 1] : count;
    }

    /** An independent copy, its arrays just long enough, for an object built when the whole file is read. */
    WrittenGroups copy() {
        WrittenGroups copy = new WrittenGroups(0, 0);
        copy.values = Arrays.copyOf(values, count);
        copy.starts = Arrays.copyOf(starts, count);
        copy.ends = Arrays.copyOf(ends, count);
        copy.keys = Arrays.copyOf(keys, count);
        copy.trees = Arrays.copyOf(trees, count);
        copy.exact = Arrays.copyOf(exact, count);
        copy.firsts = Arrays.copyOf(firsts, groupCount);
        copy.opens = Arrays.copyOf(opens, groupCount);
        copy.count = count;
        copy.anyExpression = anyExpression;
        copy.groupCount = groupCount;
        copy.target = target;
        copy.named = named;
        return copy;
    }
}
