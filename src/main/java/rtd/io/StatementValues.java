package rtd.io;

import java.util.Arrays;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.math.Vector3f;
import rtd.scene.AreaLight;

/**
 * The values of the statement being read, group by group, each with where it is written, and the rules of
 * the {@link Group}s they follow (section 4.1; Part II, "The scene file"; Part III): every number finite, a
 * radius above 0, a colour channel a whole number from 0 to 255, a direction that float can normalise, and so
 * on. {@link #build} checks every group by its rule before the builder reads them, so a builder only reads
 * values that follow it; a broken rule is an error at the value that breaks it. One is filled for every line, so that a line of
 * numbers makes no object per number.
 */
final class StatementValues {

    private final SourceText source;
    /** The names of this reading's expressions: the clock and what {@code let} defined (Part III). */
    final Names expressionNames;
    private Statement statement;
    private int line;
    private int lineStart;
    private int statementStart;
    /** What the object's names mean, once known: its material, pattern and transform. */
    private DefinedNames.ObjectNames names = DefinedNames.ObjectNames.NONE;
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
    int named = -1;

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
        named = -1;
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
        copy.named = named;
        return copy;
    }

    // ---- keeping what the reader finds ------------------------------------------------------

    /** Starts the next group, whose '(' stands at {@code offset}. */
    void openGroup(int offset) {
        if (groupCount == firsts.length) {
            firsts = Arrays.copyOf(firsts, 2 * groupCount);
            opens = Arrays.copyOf(opens, 2 * groupCount);
        }
        firsts[groupCount] = count;
        opens[groupCount++] = offset;
    }

    /** Keeps a value of the current group, written at {@code bytes[start, end)}: a word is NaN; its key or −1. */
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

    // ---- what a builder reads ---------------------------------------------------------------

    void useNames(DefinedNames.ObjectNames names) {
        this.names = names;
    }

    /** The object as its names make it ({@link DefinedNames.ObjectNames#dress}): every shape's object passes through here. */
    IGeometry dress(IGeometry object) {
        return names.dress(object);
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

    SourceText source() {
        return source;
    }

    /** How many groups were read, the optional ones among them. */
    int groupCount() {
        return groupCount;
    }

    /** How many values group {@code g} holds: for a transformation's step, its word and its numbers. */
    int size(int g) {
        return end(g) - firsts[g];
    }

    /** The group that names a pattern in the place of an object's colour, or -1. */
    int patternGroup() {
        return named;
    }

    boolean anyExpression() {
        return anyExpression;
    }

    /** Whether group {@code g} has been opened and holds a value (a name, a number) yet. */
    boolean hasValue(int g) {
        return g < groupCount && end(g) > firsts[g];
    }

    /** Whether group {@code g} was written {@code (at x|y|z)}, a point to look at. */
    boolean isTarget(int g) {
        return target == g;
    }

    /** The numbers of group {@code g} as read, for the table of the numbers that use the clock. */
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

    /** The number {@code k} of group {@code g} as written, for messages. */
    String written(int g, int k) {
        return written(firsts[g] + k);
    }

    String meaning(int g) {
        return statement.group(g).meaning();
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
        if (g == named) {
            return names.colour(); // the object's colour is its pattern's: see dress
        }
        int i = firsts[g];
        return new Color((int) channel(i), (int) channel(i + 1), (int) channel(i + 2));
    }

    /** The value of property {@code key} (its index in {@link Group#KEYS}) in group {@code g}; {@code fallback} if not given. */
    float property(int g, int key, float fallback) {
        for (int i = firsts[g]; i < end(g); i++) {
            if (keys[i] == key) {
                return values[i];
            }
        }
        return fallback;
    }

    /** Checks that the solid from group 0's end point to group {@code g}'s has an axis float can normalise. */
    void axis(int g, String shape, String help) throws StatementError {
        String why = unusable(vector(g).subtract(vector(0)));
        if (why == ZERO) {
            throw errorAtGroup(g, "the " + shape + "'s two end points are the same point", help);
        }
        if (why != null) {
            throw errorAtGroup(g, "the " + shape + "'s end points are too " + (why == LONG ? "far apart"
                    : "close together") + " to compute with in float", "give end points a distance of about 1e-15 to 1e15 apart");
        }
    }

    // ---- errors -----------------------------------------------------------------------------

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
        return errorAtValue(g, k, "", null).place;
    }

    /** Where the statement's keyword stands, as an error with no message yet. */
    SceneError placeOfStatement() {
        return errorAt(statementStart, "", null).place;
    }

    private StatementError errorAt(int offset, String message, String help) {
        return new StatementError(source.errorAt(line, lineStart, offset, message, help));
    }

    // ---- the rules --------------------------------------------------------------------------

    private static final String ZERO = "zero";
    private static final String LONG = "long";

    /**
     * Checks each group's values by its rule, then has the statement build its value into {@code out}: an error
     * at the first value that breaks a rule.
     */
    void build(SceneContents out) throws StatementError {
        for (int g = 0; g < groupCount; g++) {
            check(g, statement.group(g));
        }
        statement.builder().build(this, out);
    }

    private void check(int g, Group group) throws StatementError {
        int i = firsts[g];
        int count = end(g);
        switch (group.rule()) {
            case NAME, PATH -> { }
            case COLOUR, PAINT -> {
                for (int k = 0; k < 3 && g != named; k++) {
                    channel(i + k, k == 0 ? "red" : k == 1 ? "green" : "blue", i);
                }
            }
            case PROPERTIES -> {
                for (int j = i; j < count; j++) {
                    property(j);
                }
            }
            default -> {
                for (int j = group.rule() == Group.Rule.STEP ? i + 1 : i; j < count; j++) { // a step's word, then numbers
                    finite(j, group.size() == 3 ? "xyz".charAt(j - i) + " of the " + group.meaning() : group.meaning());
                }
                checkNumbers(group, g, i);
            }
        }
    }

    /** The rule of a group of finite numbers from value {@code i}. */
    private void checkNumbers(Group group, int g, int i) throws StatementError {
        float value = values[i];
        String meaning = group.meaning();
        switch (group.rule()) {
            case POSITIVE -> {
                if (!(value > 0)) {
                    throw errorAt(starts[i], "the " + meaning + " must be greater than 0, found " + written(i), trees[i] != null
                            ? "an expression here must be greater than 0 at every clock the scene is drawn at"
                            : value < 0 ? "without its minus sign: " + plain(-value)
                            : "a " + meaning + " of 0 leaves nothing to see; give a number greater than 0, such as 1");
                }
            }
            case AT_LEAST_ZERO -> {
                if (value < 0) {
                    throw errorAt(starts[i], "the " + meaning + " must be at least 0, found " + written(i),
                            "without its minus sign: " + written(i).substring(1));
                }
            }
            case ANGLE -> {
                if (!(value > 0 && value < 180)) {
                    throw errorAt(starts[i], "the " + meaning + " must be greater than 0 and less than 180 degrees, found "
                            + written(i), "it is the angle the picture's width spans, such as 60");
                }
            }
            case SAMPLES -> {
                samples(i, "first");
                samples(i + 1, "second");
            }
            case VIEW -> {
                if (target == g) {
                    target(g);
                } else {
                    direction(g, group.help());
                }
            }
            case DIRECTION -> direction(g, group.help());
            default -> { }
        }
    }

    /** Number {@code i}, which must be finite (not NaN, not infinite, not beyond a float's range). */
    private float finite(int i, String name) throws StatementError {
        float value = values[i];
        if (Float.isFinite(value)) {
            return value;
        }
        String written = written(i);
        boolean overflow = Hints.tooLarge(written);
        throw errorAt(starts[i], "the " + name + " must be a finite number, found " + written
                + (overflow ? ", which is too large for a float" : ""),
                overflow ? Hints.FLOAT_RANGE
                        : "NaN (not a number) and Infinity are not numbers a scene can use; give a finite number");
    }

    /** Value {@code i} of a material's properties: finite and at least 0, an ior at least 1. */
    private void property(int i) throws StatementError {
        String name = "value of '" + Group.KEYS.get(keys[i]) + "'";
        float minimum = Group.KEYS.get(keys[i]).equals("ior") ? 1 : 0;
        if (finite(i, name) < minimum) {
            throw errorAt(starts[i], "the " + name + " must be at least " + plain(minimum) + ", found " + written(i),
                    minimum > 0 ? "an index of refraction is 1 for air, 1.33 for water, 1.5 for glass"
                            : "0 turns this part of the finish off");
        }
    }

    /** Number {@code i}: an area light's samples along its {@code edge} edge, 1 to {@link AreaLight#MOST_SAMPLES}. */
    private void samples(int i, String edge) throws StatementError {
        float value = values[i];
        if (!(value >= 1 && value <= AreaLight.MOST_SAMPLES && value == Math.rint(value))) {
            throw errorAt(starts[i], "the number of samples along the " + edge + " edge must be a whole number from 1 to "
                    + AreaLight.MOST_SAMPLES + ", found " + written(i),
                    "more samples make a softer shadow and cost more shadow rays; 4|4 is a good start");
        }
    }

    /** Number {@code i} as a colour channel: an expression rounded ½ up (Part III). */
    private float channel(int i) {
        return trees[i] == null ? values[i] : (float) Math.floor(exact[i] + 0.5);
    }

    /** Number {@code i}, the {@code name} channel of the colour from {@code first}: a whole number from 0 to 255. */
    private void channel(int i, String name, int first) throws StatementError {
        float value = channel(i);
        if (trees[i] != null && !(value >= 0 && value <= 255)) {
            throw errorAt(starts[i], "the " + name + " channel must be from 0 to 255, found " + written(i),
                    "an expression in a colour is rounded to a whole number, which must be from 0 to 255");
        }
        if (!(value >= 0 && value <= 255 && value == Math.rint(value))) {
            String fractions = Hints.colourFractions(values, first);
            throw errorAt(starts[i], "the " + name + " channel must be a whole number from 0 to 255, found "
                    + written(i), fractions != null ? fractions
                            : "each channel runs from 0 (none of that colour) to 255 (all of it), in whole numbers");
        }
    }

    /** Group {@code g} as a direction (Part III, "A camera that looks at a point"): not zero, normalisable in float. */
    private void direction(int g, String zeroHelp) throws StatementError {
        String why = unusable(vector(g));
        if (why == ZERO) {
            throw errorAtValue(g, 0, "the " + meaning(g) + " must not be zero, found " + groupText(g), zeroHelp);
        }
        if (why != null) {
            throw errorAtValue(g, 0, "the " + meaning(g) + " " + groupText(g) + " is too " + why
                    + " to compute with in float", "only its direction matters: scale it to a length near 1");
        }
    }

    /** Group {@code g}, {@code (at x|y|z)}: the direction to it from the camera's position, group 0, is one as above. */
    private void target(int g) throws StatementError {
        Vector3f from = vector(0);
        String why = unusable(vector(g).subtract(from));
        if (why == ZERO) {
            throw errorAtValue(g, 0, "the camera cannot look at its own position " + groupText(g),
                    "give a point in front of the camera: (at " + plain(from.x()) + "|" + plain(from.y()) + "|"
                            + plain(from.z() - 1) + ") looks along -z");
        }
        if (why != null) {
            throw errorAtValue(g, 0, "the point " + groupText(g) + " is too " + (why == LONG ? "far from" : "near")
                    + " the camera's position to compute the view direction in float",
                    "give a point at a distance near 1 to 1000 from the camera");
        }
    }

    /** Why float cannot normalise {@code d}, whose coordinates are finite: {@link #ZERO}, {@link #LONG}, "short"; else null. */
    private static String unusable(Vector3f d) {
        float squared = d.dot(d);
        if (d.x() == 0 && d.y() == 0 && d.z() == 0) {
            return ZERO;
        }
        return Float.isInfinite(squared) ? LONG : squared < Float.MIN_NORMAL ? "short" : null;
    }

    /** Group {@code g} as written, "(0|0|0)"; "(at 0|0|0)" for a point to look at. */
    private String groupText(int g) {
        return IntStream.range(0, size(g)).mapToObj(k -> written(g, k))
                .collect(Collectors.joining("|", isTarget(g) ? "(at " : "(", ")"));
    }

    /** A number for a message or a hint without a trailing ".0": 180, -0.5. */
    static String plain(float value) {
        return value == Math.rint(value) ? String.valueOf((long) value) : String.valueOf(value);
    }

    /** The index after the last value of group {@code g}. */
    private int end(int g) {
        return g + 1 < groupCount ? firsts[g + 1] : count;
    }

    /** Value {@code i} (of all groups) as written, for messages; an expression with its value ({@link ClockText#withValue}). */
    private String written(int i) {
        String text = source.text(starts[i], ends[i]);
        Expression tree = trees[i];
        return tree == null ? text : ClockText.withValue(text, values[i], tree.usesClock(), expressionNames.clock);
    }
}
