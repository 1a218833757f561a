package rtd.io;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The names an expression may use while one scene file is read (Part III, "Expressions, named values and the
 * clock"): {@code clock}, whose value this reading is for (0 unless the command line says otherwise),
 * {@code pi}, and each name a {@code let} above the line being read defined. It also notes whether any
 * number used the clock: a scene that never does draws the same picture at every clock.
 */
final class Names {

    private final double clock;
    private final Map<String, Expression> defined = new HashMap<>();
    private final Map<String, Integer> lines = new HashMap<>();
    private final Map<String, Integer> broken = new HashMap<>();
    private boolean clockUsed;
    /** Where the reading notes each statement's numbers that use the clock, for {@link SceneFile#withClock}. */
    final ClockedScene.Recorder recorder;

    /** The names of a reading at {@code clock}, whose numbers that use the clock nobody asks for. */
    Names(double clock) {
        this(clock, new ClockedScene.Recorder());
    }

    /** The names of a reading at {@code clock} that tells {@code recorder} the numbers that use it. */
    Names(double clock, ClockedScene.Recorder recorder) {
        this.clock = clock;
        this.recorder = recorder;
    }

    /**
     * Words a {@code let} may not define: the clock, pi, the functions, and the words of the number format and
     * of {@code (at x|y|z)}; made when a name is first checked, so a file of plain numbers never needs them.
     */
    private static final class Reserved {
        static final Set<String> WORDS = reserved();
    }

    private static Set<String> reserved() {
        List<String> words = new ArrayList<>(ExpressionFunction.NAMES);
        words.addAll(List.of("clock", "pi", "at", "NaN", "Infinity"));
        return Set.copyOf(words);
    }

    double clock() {
        return clock;
    }

    /** Whether some number of the file used the clock, directly or through a {@code let}. */
    boolean clockUsed() {
        return clockUsed;
    }

    /** Notes that a number used the clock. */
    void noteClockUse() {
        clockUsed = true;
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

    /** Whether {@code word} is one a {@code let} may not take. */
    static boolean isReserved(String word) {
        return Reserved.WORDS.contains(word);
    }

    /** The line of the {@code let} that defined {@code name}, or of the broken one that tried to; or null. */
    Integer lineOf(String name) {
        Integer line = lines.get(name);
        return line != null ? line : broken.get(name);
    }

    /** Whether {@code name} has a {@code let} with a mistake, which is reported there. */
    boolean isBroken(String name) {
        return broken.containsKey(name);
    }

    /** Defines {@code name} as {@code definition}, by the {@code let} at {@code line}. */
    void define(String name, Expression definition, int line) {
        defined.put(name, definition);
        lines.put(name, line);
    }

    /** Notes a {@code let} of {@code name} at {@code line} that has a mistake: its uses are not told the name is unknown. */
    void defineBroken(String name, int line) {
        if (!lines.containsKey(name)) {
            broken.putIfAbsent(name, line);
        }
    }

    /** The names known now, those of broken lets among them, for "did you mean …?". */
    List<String> known() {
        List<String> known = new ArrayList<>(List.of("clock", "pi"));
        known.addAll(defined.keySet());
        known.addAll(broken.keySet());
        return known;
    }
}
