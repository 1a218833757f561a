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

    /**
     * Keeps a value of the current group, written at {@code bytes[start, end)}: a name or path is NaN; its key or −1.
     */
    void add(float value, int start, int end, int key) {
        if (count == values.length) {
            resize(2 * count);
        }
        values[count] = value;
        starts[count] = start;
        ends[count] = end;
        keys[count++] = key;
    }

    /** Marks the value kept last as written as the expression {@code tree}, whose value is {@code exactValue}. */
    void markExpression(double exactValue, Expression tree) {
        trees[count - 1] = tree;
        exact[count - 1] = exactValue;
        anyExpression = true;
    }

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
        copy.values = values;
        copy.starts = starts;
        copy.ends = ends;
        copy.keys = keys;
        copy.trees = trees;
        copy.exact = exact;
        copy.count = count;
        copy.resize(count);
        copy.firsts = Arrays.copyOf(firsts, groupCount);
        copy.opens = Arrays.copyOf(opens, groupCount);
        copy.anyExpression = anyExpression;
        copy.groupCount = groupCount;
        copy.target = target;
        copy.named = named;
        return copy;
    }

    /** Makes the values' arrays {@code length} long: new arrays, the values kept. */
    private void resize(int length) {
        values = Arrays.copyOf(values, length);
        starts = Arrays.copyOf(starts, length);
        ends = Arrays.copyOf(ends, length);
        keys = Arrays.copyOf(keys, length);
        trees = Arrays.copyOf(trees, length);
        exact = Arrays.copyOf(exact, length);
    }
}
