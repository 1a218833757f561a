package rtd.io;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import rtd.geometry.Pattern;
import rtd.math.Matrix4;

/**
 * The names a scene file defines as it is read, and the builders of those definitions. An expression (Part III,
 * "Expressions, named values and the clock") may use {@code clock}, {@code pi} and each name a {@code let:} above
 * defined; it notes whether any number used the clock. Objects name what {@code pattern:} (<i>The Ray Tracer
 * Challenge</i>, chapter 10) and {@code transform:} (chapters 4 and 14) define, resolved by {@link DefinedNames}
 * once the file is read; a transform's steps apply in the order written, {@code M = T_k ⋯ T_2·T_1}.
 */
final class Names {

    static final String STEP_HELP = "write a step as (scale 2), (scale 1|2|1), (rotate_y 30) or (translate 0|1|0)";
    private static final List<String> OPERATIONS = List.of("scale", "rotate_x", "rotate_y", "rotate_z", "translate");

    final double clock;
    private final Map<String, Expression> defined = new HashMap<>();
    /** The line of each name's {@code let}, those with a mistake among them (which are not {@link #defined}). */
    private final Map<String, Integer> lines = new HashMap<>();
    boolean clockUsed;
    /** Where the reading notes each statement's numbers that use the clock, for {@link SceneFile#withClock}. */
    final ClockedScene.Recorder recorder;

    Names(double clock, ClockedScene.Recorder recorder) {
        this.clock = clock;
        this.recorder = recorder;
    }

    /** The names defined so far, for lines read on their own, which note what they use in a recorder of their own. */
    Names forPart() {
        Names part = new Names(clock, new ClockedScene.Recorder());
        part.defined.putAll(defined);
        part.lines.putAll(lines);
        return part;
    }

    /** Whether this reading, made by {@link #forPart} from {@code before}, used no clock and defined no name. */
    boolean definesNothingBeyond(Names before) {
        return !clockUsed && lines.size() == before.lines.size();
    }

    /** The words a {@code let} may not define; made when first asked, so a file of plain numbers never needs them. */
    private static final class Reserved {
        static final Set<String> WORDS = Set.copyOf(Stream.concat(Expression.Function.NAMES.stream(),
                Stream.of("clock", "pi", "at", "NaN", "Infinity")).toList());
    }

    /** The name {@code word} written at byte {@code start}, or null if it is not known (yet). */
    Expression lookUp(String word, int start) {
        if (word.equals("clock")) {
            return new Expression.Clock(start);
        }
        if (word.equals("pi")) {
            return new Expression.Name("pi", new Expression.Number(Math.PI, start), start);
        }
        Expression definition = defined.get(word);
        return definition == null ? null : new Expression.Name(word, definition, start);
    }

    /** Whether {@code name} has a {@code let} with a mistake, which is reported there. */
    boolean isBroken(String name) {
        return lines.containsKey(name) && !defined.containsKey(name);
    }

    /** The names known now, those of broken lets among them, for "did you mean …?". */
    List<String> known() {
        return Stream.concat(Stream.of("clock", "pi"), lines.keySet().stream()).toList();
    }

    /** {@code let:(name):(expression)}: defines the name of group 0 as the expression of group 1. */
    static void let(StatementValues v) throws SceneException {
        String name = v.name(0);
        if (!ExpressionParser.isLetter((byte) name.charAt(0)) || name.indexOf('-') >= 0) {
            throw v.errorAtValue(0, 0, "the name '" + name + "' cannot be defined: a name starts with a letter, then "
                    + "letters, digits or '_'", "such as let:(size):(1)");
        }
        if (Reserved.WORDS.contains(name)) {
            throw v.errorAtValue(0, 0, "'" + name + "' cannot be defined: it is a word of the expressions",
                    "choose another name; clock, pi and the functions (sin, cos, sqrt, …) keep their meaning");
        }
        Names names = v.expressionNames;
        Integer earlier = names.lines.get(name);
        if (earlier != null) {
            throw v.errorAtValue(0, 0, "a second let of '" + name + "': each name is defined once",
                    "the first '" + name + "' is at line " + earlier);
        }
        names.defined.put(name, v.expression(1));
        names.lines.put(name, v.line());
    }

    /** Notes that the {@code let} being read has a mistake, once its name is read: its uses are then left out. */
    static void brokenLet(StatementValues v) {
        if (v.hasValue(0)) {
            v.expressionNames.lines.putIfAbsent(v.name(0), v.line());
        }
    }

    /** {@code pattern:(name):(kind):(R|G|B):(R|G|B)[:(transform)]}; the transform's name is resolved later. */
    static void pattern(StatementValues v, SceneContents out) throws SceneException {
        String word = v.name(1);
        List<String> kinds = Arrays.stream(Pattern.Kind.values()).map(Pattern.Kind::word).toList();
        if (!kinds.contains(word)) {
            throw v.errorAtValue(1, 0, "unknown kind of pattern '" + word + "'",
                    Hints.nearestOrList(word, kinds, "kinds"));
        }
        Pattern.Kind kind = Pattern.Kind.values()[kinds.indexOf(word)];
        out.define(v.name(0), "pattern", new Pattern(kind, v.colour(2), v.colour(3), Matrix4.IDENTITY),
                v.groupCount() > 4 ? v.name(4) : null);
    }

    /** {@code transform:(name):(step)[:(step)…]}: the steps composed in the order written. */
    static void transform(StatementValues v, SceneContents out) throws SceneException {
        Matrix4 m = Matrix4.IDENTITY;
        for (int g = 1; g < v.groupCount(); g++) {
            m = m.then(step(v, g));
        }
        out.define(v.name(0), "transform", m, null);
    }

    /** The step of group {@code g}: its word, then its numbers, each checked where it is written. */
    private static Matrix4 step(StatementValues v, int g) throws SceneException {
        String word = v.name(g);
        int count = v.size(g) - 1; // the word, then its numbers
        if (!OPERATIONS.contains(word)) {
            throw v.errorAtValue(g, 0, "unknown step '" + word + "' in a transform",
                    Hints.nearestOrList(word, OPERATIONS, "steps"));
        }
        boolean scale = word.equals("scale");
        int wanted = word.startsWith("rotate") ? 1 : 3;
        if (!(count == wanted || scale && count == 1)) {
            String takes = scale ? "1 number (s) or 3 (sx|sy|sz)"
                    : wanted == 1 ? "1 number, an angle in degrees" : "3 numbers (x|y|z)";
            throw v.errorAtValue(g, 0, "'" + word + "' takes " + takes + ", found " + count, STEP_HELP);
        }
        double[] n = new double[3];
        for (int k = 0; k < count; k++) {
            n[k] = v.number(g, 1 + k);
            if (scale && n[k] == 0) {
                throw v.errorAtValue(g, 1 + k, "a scale of 0 flattens the object to nothing",
                        "scale by a number other than 0, such as 1 to leave that axis as it is");
            }
        }
        return switch (word) {
            case "scale" -> count == 1 ? Matrix4.scale(n[0], n[0], n[0]) : Matrix4.scale(n[0], n[1], n[2]);
            case "rotate_x" -> Matrix4.rotateX(n[0]);
            case "rotate_y" -> Matrix4.rotateY(n[0]);
            case "rotate_z" -> Matrix4.rotateZ(n[0]);
            default -> Matrix4.translate(n[0], n[1], n[2]);
        };
    }
}
