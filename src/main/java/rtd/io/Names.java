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
 * {@code pi}, and each name a {@code let} above the line being read defined. It also notes whether any
 * number used the clock: a scene that never does draws the same picture at every clock.
 */
final class Names {

    final double clock;
    private final Map<String, Expression> defined = new HashMap<>();
    /**
     * The line of each name's {@code let}, those with a mistake among them (a broken name is not in {@link #defined}).
     */
    private final Map<String, Integer> lines = new HashMap<>();
    /** Whether some number of the file used the clock, directly or through a {@code let}. */
    boolean clockUsed;
    /** Where the reading notes each statement's numbers that use the clock, for {@link SceneFile#withClock}. */
    final ClockedScene.Recorder recorder;

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

    static boolean isReserved(String word) {
        return Reserved.WORDS.contains(word);
    }

    /** The line of the {@code let} that defined {@code name}, or of the broken one that tried to; or null. */
    Integer lineOf(String name) {
        return lines.get(name);
    }

    /** Whether {@code name} has a {@code let} with a mistake, which is reported there. */
    boolean isBroken(String name) {
        return lines.containsKey(name) && !defined.containsKey(name);
    }

    /** Defines {@code name} as {@code definition}, by the {@code let} at {@code line}. */
    void define(String name, Expression definition, int line) {
        defined.put(name, definition);
        lines.put(name, line);
    }

    /** Notes a {@code let} of {@code name} at {@code line} that has a mistake: its uses are not told the name is unknown. */
    void defineBroken(String name, int line) {
        lines.putIfAbsent(name, line);
    }

    /** The names known now, those of broken lets among them, for "did you mean …?". */
    List<String> known() {
        List<String> known = new ArrayList<>(List.of("clock", "pi"));
        known.addAll(lines.keySet());
        return known;
    }
}
