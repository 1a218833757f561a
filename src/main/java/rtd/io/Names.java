package rtd.io;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

/**
 * The names an expression may use while one scene file is read (Part III, "Expressions, named values and the
 * clock"): {@code clock}, whose value this reading is for (0 unless the command line says otherwise),
 * {@code pi}, and each name a {@code let:} above the line being read defined. A {@code let} name is a letter,
 * then letters, digits or '_'; not a word the expressions use, and not defined twice. It also notes whether any
 * number used the clock: a scene that never does draws the same picture at every clock.
 */
final class Names {

    final double clock;
    private final Map<String, Expression> defined = new HashMap<>();
    /** The line of each name's {@code let}, those with a mistake among them (a broken name is not in {@link #defined}). */
    private final Map<String, Integer> lines = new HashMap<>();
    /** Whether some number of the file used the clock, directly or through a {@code let}. */
    boolean clockUsed;
    /** Where the reading notes each statement's numbers that use the clock, for {@link SceneFile#withClock}. */
    final ClockedScene.Recorder recorder;

    Names(double clock, ClockedScene.Recorder recorder) {
        this.clock = clock;
        this.recorder = recorder;
    }

    /** The words a {@code let} may not define; made when first asked, so a file of plain numbers never needs them. */
    private static final class Reserved {
        static final Set<String> WORDS = Set.copyOf(Stream.concat(ExpressionFunction.NAMES.stream(),
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
        List<String> known = new ArrayList<>(List.of("clock", "pi"));
        known.addAll(lines.keySet());
        return known;
    }

    /** {@code let:(name):(expression)}: defines the name of group 0 as the expression of group 1. */
    static void let(StatementValues v) throws StatementError {
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
}
