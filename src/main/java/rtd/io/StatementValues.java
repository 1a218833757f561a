package rtd.io;

import java.util.Arrays;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.math.Vector3f;

/**
 * The values of the statement being read, group by group, and the rules they must follow (section 4.1; Part
 * II, "The scene file"): every number finite, a radius above 0, a direction not zero, a colour channel a
 * whole number from 0 to 255, and so on. A builder asks for its groups by index; a broken rule is an error
 * at the value that breaks it.
 */
final class StatementValues {

    private final SourceText source;
    private final WrittenGroups groups;
    /** The names of this reading's expressions: the clock and what {@code let} defined (Part III). */
    final Names expressionNames;
    private Statement statement;
    private int line;
    private int lineStart;
    private int statementStart;
    /** What the object's names mean, once known: its material, pattern and transform. */
    private DefinedNames.ObjectNames names;

    /** The values of the statements read into {@code groups}, one after the other. */
    StatementValues(SourceText source, WrittenGroups groups, Names expressionNames) {
        this.source = source;
        this.groups = groups;
        this.expressionNames = expressionNames;
    }

    /** Starts a statement whose keyword stands at byte {@code statementStart} of a line. */
    void begin(Statement statement, int line, int lineStart, int statementStart) {
        this.statement = statement;
        this.line = line;
        this.lineStart = lineStart;
        this.statementStart = statementStart;
        this.names = DefinedNames.ObjectNames.NONE;
        groups.clear();
    }

    /** An independent copy, for an object built when the whole file is read. */
    StatementValues copy() {
        StatementValues copy = new StatementValues(source, groups.copy(), expressionNames);
        copy.statement = statement;
        copy.line = line;
        copy.lineStart = lineStart;
        copy.statementStart = statementStart;
        return copy;
    }

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
        return groups.groupCount;
    }

    /** How many values group {@code g} holds: for a transformation's step, its word and its numbers. */
    int size(int g) {
        return groups.end(g) - groups.firsts[g];
    }

    /** The group that names a pattern in the place of an object's colour, or -1. */
    int patternGroup() {
        return groups.named;
    }

    boolean anyExpression() {
        return groups.anyExpression;
    }

    /** Whether group {@code g} has been opened and holds a value (a name, a number) yet. */
    boolean hasValue(int g) {
        return g < groups.groupCount && groups.end(g) > groups.firsts[g];
    }

    /** Whether group {@code g} was written {@code (at x|y|z)}, a point to look at. */
    boolean isTarget(int g) {
        return groups.target == g;
    }

    /** The numbers of group {@code g} as read, unchecked, for the table of the numbers that use the clock. */
    float[] numbers(int g) {
        return Arrays.copyOfRange(groups.values, groups.firsts[g], groups.end(g));
    }

    /** The expression of number {@code k} of group {@code g}, or null for a plain number. */
    Expression tree(int g, int k) {
        return groups.trees[groups.firsts[g] + k];
    }

    String name(int g) {
        return written(groups.firsts[g]);
    }

    /** The number {@code k} of group {@code g} as written, for messages. */
    String written(int g, int k) {
        return written(groups.firsts[g] + k);
    }

    String meaning(int g) {
        int own = statement.groups().size();
        return g < own ? statement.groups().get(g).meaning() : statement.optional(g - own).meaning();
    }

    /** An error at the '(' of group {@code g}. */
    StatementError errorAtGroup(int g, String message, String help) {
        return errorAt(groups.opens[g], message, help);
    }

    /** An error at number {@code k} of group {@code g}, or at the name of a name group ({@code k = 0}). */
    StatementError errorAtValue(int g, int k, String message, String help) {
        return errorAt(groups.starts[groups.firsts[g] + k], message, help);
    }

    /** Where value {@code k} of group {@code g} stands, as an error with no message yet. */
    SceneError placeOfValue(int g, int k) {
        return errorAtValue(g, k, "", null).place;
    }

    /** Where the statement's keyword stands, as an error with no message yet. */
    SceneError placeOfStatement() {
        return errorAt(statementStart, "", null).place;
    }

    // ---- the rules --------------------------------------------------------------------------

    /** Value {@code k} of group {@code g}, which must be finite. */
    float number(int g, int k) throws StatementError {
        return finite(groups.firsts[g] + k, meaning(g));
    }

    /** The one value of group {@code g}, finite, as an expression: the one written, or the plain number as read. */
    Expression expression(int g) throws StatementError {
        int i = groups.firsts[g];
        float value = finite(i, meaning(g));
        return groups.trees[i] != null ? groups.trees[i] : new Expression.Number(value, groups.starts[i]);
    }

    /** The one number of group {@code g}, which must be finite and greater than 0 (a radius, a zoom). */
    float positive(int g) throws StatementError {
        int i = groups.firsts[g];
        float value = finite(i, meaning(g));
        if (value > 0) {
            return value;
        }
        throw errorAt(groups.starts[i], "the " + meaning(g) + " must be greater than 0, found " + written(i),
                groups.trees[i] != null ? "an expression here must be greater than 0 at every clock the scene is drawn at"
                        : value < 0 ? "without its minus sign: " + plain(-value)
                        : "a " + meaning(g) + " of 0 leaves nothing to see; give a number greater than 0, such as 1");
    }

    /** The one number of group {@code g}, finite and strictly between {@code low} and {@code high}. */
    float between(int g, float low, float high, String unit, String help) throws StatementError {
        int i = groups.firsts[g];
        float value = finite(i, meaning(g));
        if (value > low && value < high) {
            return value;
        }
        throw errorAt(groups.starts[i], "the " + meaning(g) + " must be greater than " + plain(low) + " and less than "
                + plain(high) + " " + unit + ", found " + written(i), help);
    }

    Vector3f vector(int g) throws StatementError {
        int i = groups.firsts[g];
        for (int k = 0; k < 3; k++) {
            if (!Float.isFinite(groups.values[i + k])) {
                finite(i + k, "xyz".charAt(k) + " of the " + meaning(g));
            }
        }
        return new Vector3f(groups.values[i], groups.values[i + 1], groups.values[i + 2]);
    }

    /** The three numbers of group {@code g}: a colour, each channel a whole number from 0 to 255. */
    Color colour(int g) throws StatementError {
        if (g == groups.named) {
            return names.colour(); // the object's colour is its pattern's: see dress
        }
        int i = groups.firsts[g];
        return new Color(channel(i, "red", i), channel(i + 1, "green", i), channel(i + 2, "blue", i));
    }

    /** The value of {@code key} in group {@code g}'s properties, finite and at least {@code minimum}; else {@code fallback}. */
    float property(int g, String key, float fallback, float minimum) throws StatementError {
        int index = statement.groups().get(g).keys().indexOf(key);
        for (int i = groups.firsts[g]; i < groups.end(g); i++) {
            if (groups.keys[i] == index) {
                String name = "value of '" + key + "'";
                float value = finite(i, name);
                if (value >= minimum) {
                    return value;
                }
                throw errorAt(groups.starts[i], "the " + name + " must be at least " + plain(minimum) + ", found " + written(i),
                        minimum > 0 ? "an index of refraction is 1 for air, 1.33 for water, 1.5 for glass"
                                : "0 turns this part of the finish off");
            }
        }
        return fallback;
    }

    /** Number {@code i}, which must be finite (not NaN, not infinite, not beyond a float's range). */
    private float finite(int i, String name) throws StatementError {
        float value = groups.values[i];
        if (Float.isFinite(value)) {
            return value;
        }
        String written = written(i);
        boolean overflow = Hints.tooLarge(written);
        throw errorAt(groups.starts[i], "the " + name + " must be a finite number, found " + written
                + (overflow ? ", which is too large for a float" : ""),
                overflow ? Hints.FLOAT_RANGE
                        : "NaN (not a number) and Infinity are not numbers a scene can use; give a finite number");
    }

    /** Number {@code i}, the {@code name} channel of the colour from {@code first}; an expression rounded ½ up (Part III). */
    private int channel(int i, String name, int first) throws StatementError {
        float value = groups.trees[i] == null ? groups.values[i] : (float) Math.floor(groups.exact[i] + 0.5);
        if (groups.trees[i] != null && !(value >= 0 && value <= 255)) {
            throw errorAt(groups.starts[i], "the " + name + " channel must be from 0 to 255, found " + written(i),
                    "an expression in a colour is rounded to a whole number, which must be from 0 to 255");
        }
        if (!(value >= 0 && value <= 255 && value == Math.rint(value))) {
            String fractions = Hints.colourFractions(groups.values, first);
            throw errorAt(groups.starts[i], "the " + name + " channel must be a whole number from 0 to 255, found "
                    + written(i), fractions != null ? fractions
                            : "each channel runs from 0 (none of that colour) to 255 (all of it), in whole numbers");
        }
        return (int) value;
    }

    /** A number for a message or a hint without a trailing ".0": 180, -0.5. */
    static String plain(float value) {
        return value == Math.rint(value) ? String.valueOf((long) value) : String.valueOf(value);
    }

    private StatementError errorAt(int offset, String message, String help) {
        return new StatementError(source.errorAt(line, lineStart, offset, message, help));
    }

    /** Value {@code i} (of all groups) as written, for messages; an expression with its value ({@link ClockedScene#withValue}). */
    private String written(int i) {
        String text = source.text(groups.starts[i], groups.ends[i]);
        Expression tree = groups.trees[i];
        return tree == null ? text
                : ClockedScene.withValue(text, groups.values[i], tree.usesClock(), expressionNames.clock);
    }
}
