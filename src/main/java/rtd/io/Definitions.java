package rtd.io;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import rtd.geometry.Pattern;
import rtd.math.Matrix4;

/**
 * The builders of Part III's definitions: {@code pattern:} (<i>The Ray Tracer Challenge</i>, chapter 10) and
 * {@code transform:} (chapters 4 and 14), which objects name, and {@code let:} ("Expressions, named values and
 * the clock"), which expressions on the lines below name. A transform's steps apply in the order written,
 * {@code M = T_k ⋯ T_2·T_1}; each step is checked where it is written. A {@code let} name is a letter, then
 * letters, digits or '_'; not a word the expressions use, and not defined twice; a plain number is kept as a
 * statement would read it, an expression as its tree.
 */
final class Definitions {

    private static final List<String> OPERATIONS = List.of("scale", "rotate_x", "rotate_y", "rotate_z", "translate");
    static final String STEP_HELP = "write a step as (scale 2), (scale 1|2|1), (rotate_y 30) or (translate 0|1|0)";

    private Definitions() {
    }

    /** {@code pattern:(name):(kind):(R|G|B):(R|G|B)[:(transform)]}; the transform's name is resolved later. */
    static void pattern(StatementValues v, SceneContents out) throws StatementError {
        String word = v.name(1);
        Pattern.Kind kind = Arrays.stream(Pattern.Kind.values()).filter(k -> k.word().equals(word)).findFirst().orElse(null);
        if (kind == null) {
            List<String> kinds = Arrays.stream(Pattern.Kind.values()).map(Pattern.Kind::word).toList();
            String nearest = Hints.nearest(word, kinds);
            throw v.errorAtValue(1, 0, "unknown kind of pattern '" + word + "'", nearest != null
                    ? "did you mean '" + nearest + "'?" : "the kinds are " + Hints.quoted(kinds, "and"));
        }
        Pattern pattern = new Pattern(kind, v.colour(2), v.colour(3), Matrix4.IDENTITY);
        out.pattern(v.name(0), pattern, v.groupCount() > 4 ? v.name(4) : null);
    }

    /** {@code transform:(name):(step)[:(step)…]}: the steps composed in the order written. */
    static void transform(StatementValues v, SceneContents out) throws StatementError {
        Matrix4 m = Matrix4.IDENTITY;
        for (int g = 1; g < v.groupCount(); g++) {
            m = m.then(step(v, g));
        }
        out.transform(v.name(0), m);
    }

    /** The step of group {@code g}: its word, then its numbers. */
    private static Matrix4 step(StatementValues v, int g) throws StatementError {
        String word = v.name(g);
        int count = v.size(g) - 1; // the word, then its numbers
        if (!OPERATIONS.contains(word)) {
            String nearest = Hints.nearest(word.toLowerCase(Locale.ROOT), OPERATIONS);
            throw v.errorAtValue(g, 0, "unknown step '" + word + "' in a transform", nearest != null
                    ? "did you mean '" + nearest + "'?" : "the steps are " + Hints.quoted(OPERATIONS, "and"));
        }
        boolean scale = word.equals("scale");
        int wanted = word.startsWith("rotate") ? 1 : 3;
        if (!(count == wanted || scale && count == 1)) {
            String takes = scale ? "1 number (s) or 3 (sx|sy|sz)" : wanted == 1 ? "1 number, an angle in degrees" : "3 numbers (x|y|z)";
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

    /** {@code let:(name):(expression)}: defines the name of group 0 as the expression of group 1. */
    static void let(StatementValues v) throws StatementError {
        String name = v.name(0);
        if (!ExpressionParser.isLetter((byte) name.charAt(0)) || name.indexOf('-') >= 0) {
            throw v.errorAtValue(0, 0, "the name '" + name + "' cannot be defined: a name starts with a letter, then "
                    + "letters, digits or '_'", "such as let:(size):(1)");
        }
        if (Names.isReserved(name)) {
            throw v.errorAtValue(0, 0, "'" + name + "' cannot be defined: it is a word of the expressions",
                    "choose another name; clock, pi and the functions (sin, cos, sqrt, …) keep their meaning");
        }
        Integer earlier = v.expressionNames.lineOf(name);
        if (earlier != null) {
            throw v.errorAtValue(0, 0, "a second let of '" + name + "': each name is defined once",
                    "the first '" + name + "' is at line " + earlier);
        }
        v.expressionNames.define(name, v.expression(1), v.line());
    }

    /** Notes that the {@code let} being read has a mistake, once its name is read: its uses are then left out. */
    static void brokenLet(StatementValues v) {
        if (v.hasValue(0)) {
            v.expressionNames.defineBroken(v.name(0), v.line());
        }
    }
}
