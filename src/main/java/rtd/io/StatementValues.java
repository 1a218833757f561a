package rtd.io;

import java.util.Arrays;
import java.util.stream.IntStream;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.math.Vector3f;

/**
 * The values of the statement being read, group by group, each with where it is written (section 4.1; Part
 * II, "The scene file"). {@link #build} checks each group's rule first, so a builder reads only values that
 * follow the rules. One is refilled for every line, so that a line makes no object per number.
 */
final class StatementValues {

    final SourceText source;
    /** The names of this reading's expressions: the clock and what {@code let} defined (Part III). */
    final Names expressionNames;
    private Statement statement;
    private int line;
    private int lineStart;
    private int statementStart;
    /** What the object's names mean, once known: its material, pattern and transform; it dresses each object. */
    DefinedNames.ObjectNames names = DefinedNames.ObjectNames.NONE;
    // Each value: its number (NaN for a word), where it is written, its property's index in Group.KEYS (or −1),
    // and for an expression its tree and its value in double precision (else null and unset).
    private float[] values = new float[16];
    private int[] starts = new int[16];
    private int[] ends = new int[16];
    private int[] keys = new int[16];
    private Expression[] trees = new Expression[16];
    private double[] exact = new double[16];
    private boolean anyExpression;
    private int count;
    /** Each group's first value and its '('. */
    private int[] firsts = new int[8];
    private int[] opens = new int[8];
    private int groupCount;
    /** The group written {@code (at x|y|z)}, a point to look at, or −1. */
    int target = -1;
    /** The group that holds a pattern's name where an object's colour stands, or −1. */
    int patternGroup = -1;

    StatementValues(SourceText source, Names expressionNames) {
        this.source = source;
        this.expressionNames = expressionNames;
    }

    /** Starts a statement whose keyword stands at byte {@code statementStart} of a line. */
    void begin(Statement statement, int line, int lineStart, int statementStart) {
        this.statement = statement;
        this.line = line;
        this.lineStart = lineStart;
        this.statementStart = statementStart;
        this.names = DefinedNames.ObjectNames.NONE;
        if (anyExpression) { // only then does a tree need forgetting: a plain number's stays null
            Arrays.fill(trees, 0, count, null);
            anyExpression = false;
        }
        count = 0;
        groupCount = 0;
        target = -1;
        patternGroup = -1;
    }

    /** An independent copy, its arrays just long enough, for an object built when the whole file is read. */
    StatementValues copy() {
        StatementValues copy = new StatementValues(source, expressionNames);
        copy.begin(statement, line, lineStart, statementStart);
        copy.values = Arrays.copyOf(values, count);
        copy.starts = Arrays.copyOf(starts, count);
        copy.ends = Arrays.copyOf(ends, count);
        copy.keys = Arrays.copyOf(keys, count);
        copy.trees = Arrays.copyOf(trees, count);
        copy.exact = Arrays.copyOf(exact, count);
        copy.firsts = Arrays.copyOf(firsts, groupCount);
        copy.opens = Arrays.copyOf(opens, groupCount);
        copy.anyExpression = anyExpression;
        copy.count = count;
        copy.groupCount = groupCount;
        copy.target = target;
        copy.patternGroup = patternGroup;
        return copy;
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

    /** Keeps a value of the current group, written at {@code [start, end)}: a word is NaN; its key or −1. */
    void add(float value, int start, int end, int key) {
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
        keys[count++] = key;
    }

    /** Marks the value kept last as written as the expression {@code tree}, whose value is {@code exactValue}. */
    void markExpression(double exactValue, Expression tree) {
        trees[count - 1] = tree;
        exact[count - 1] = exactValue;
        anyExpression = true;
    }

    boolean lastHasKey(int key) {
        return IntStream.range(firsts[groupCount - 1], count).anyMatch(i -> keys[i] == key);
    }

    /** Checks each group by its rule, then builds into {@code out}. */
    void build(SceneContents out) throws SceneException {
        for (int g = 0; g < groupCount; g++) {
            statement.group(g).check(this, g);
        }
        statement.builder().build(this, out);
    }

    /** The finish of the object: the material its last group names, or {@link Material#DEFAULT}. */
    Material material() {
        return names.material();
    }

    Statement statement() {
        return statement;
    }

    int line() {
        return line;
    }

    int groupCount() {
        return groupCount;
    }

    /** How many values group {@code g} holds: for a transformation's step, its word and its numbers. */
    int size(int g) {
        return end(g) - firsts[g];
    }

    boolean anyExpression() {
        return anyExpression;
    }

    /** Whether group {@code g} has been opened and holds a value yet. */
    boolean hasValue(int g) {
        return g < groupCount && end(g) > firsts[g];
    }

    float[] numbers(int g) {
        return Arrays.copyOfRange(values, firsts[g], end(g));
    }

    /** The expression of number {@code k} of group {@code g}, or null for a plain number. */
    Expression tree(int g, int k) {
        return trees[firsts[g] + k];
    }

    String name(int g) {
        return written(firsts[g]);
    }

    String written(int g, int k) {
        return written(firsts[g] + k);
    }

    float number(int g, int k) {
        return values[firsts[g] + k];
    }

    /** The one value of group {@code g} as an expression: the one written, or the plain number as read. */
    Expression expression(int g) {
        int i = firsts[g];
        return trees[i] != null ? trees[i] : new Expression.Number(values[i], starts[i]);
    }

    Vector3f vector(int g) {
        int i = firsts[g];
        return new Vector3f(values[i], values[i + 1], values[i + 2]);
    }

    Color colour(int g) {
        if (g == patternGroup) {
            return names.colour(); // the object's colour is its pattern's: see dress
        }
        return new Color((int) channel(g, 0), (int) channel(g, 1), (int) channel(g, 2));
    }

    /** Channel {@code k} of colour group {@code g}: an expression rounded ½ up (Part III). */
    float channel(int g, int k) {
        int i = firsts[g] + k;
        return trees[i] == null ? values[i] : (float) Math.floor(exact[i] + 0.5);
    }

    /** The index in {@link Group#KEYS} of property {@code k} of group {@code g}. */
    int key(int g, int k) {
        return keys[firsts[g] + k];
    }

    SceneException errorAtGroup(int g, String message, String help) {
        return errorAt(opens[g], message, help);
    }

    /** An error at number {@code k} of group {@code g}, or at the name of a name group ({@code k = 0}). */
    SceneException errorAtValue(int g, int k, String message, String help) {
        return errorAt(starts[firsts[g] + k], message, help);
    }

    /** Where value {@code k} of group {@code g} stands, as an error with no message yet. */
    SceneError placeOfValue(int g, int k) {
        return errorAtValue(g, k, "", null).place;
    }

    /** Where the statement's keyword stands, as an error with no message yet. */
    SceneError placeOfStatement() {
        return errorAt(statementStart, "", null).place;
    }

    private SceneException errorAt(int offset, String message, String help) {
        return new SceneException(source.errorAt(line, lineStart, offset, message, help));
    }

    private int end(int g) {
        return g + 1 < groupCount ? firsts[g + 1] : count;
    }

    /** Value {@code i} as written, for messages; an expression with its value ({@link ClockedScene#withValue}). */
    private String written(int i) {
        String text = source.text(starts[i], ends[i]);
        Expression tree = trees[i];
        return tree == null ? text : ClockedScene.withValue(text, values[i], tree.usesClock(), expressionNames.clock);
    }
}
