package rtd.io;

import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Finds the word a misspelt one was probably meant to be ("did you mean 'sphere'?"), and the
 * statements meant by words that share no spelling with them ({@code camera}, {@code kugel}).
 */
final class Suggestions {

    /**
     * Words people write for a statement, in English, in German (the paper's language) and from
     * other tools, that are too far from its keyword for {@link #nearest} to find it. Looked up
     * before the spelling: "bg" is two edits from "box", but means the background.
     */
    private static final Map<String, List<String>> SYNONYMS = new HashMap<>();

    static {
        synonyms("camera cam kamera view eye", "orthographic_camera", "perspective_camera");
        synonyms("ortho orthographic orthocamera", "orthographic_camera");
        synonyms("perspective persp perspectivecamera", "perspective_camera");
        synonyms("ball kugel circle kreis globe", "sphere");
        synonyms("background hintergrund bg color colour farbe backgroundcolor sky", "ambient");
        synonyms("lamp licht lichtquelle pointlight point_light lightsource light_source sun", "light");
        synonyms("floor ground boden ebene wall", "plane");
        synonyms("cube cuboid quader wuerfel aabb", "box");
        synonyms("tri dreieck face", "triangle");
        synonyms("obj model modell", "mesh");
        synonyms("mat finish surface", "material");
    }

    private Suggestions() {
    }

    /** The help for an unknown statement keyword: "did you mean …?", or the list of keywords. */
    static String keywordHelp(String word) {
        List<String> meant = SYNONYMS.get(word.toLowerCase(Locale.ROOT));
        if (meant != null) {
            return "did you mean '" + String.join("' or '", meant) + "'?";
        }
        String nearest = nearest(word, Grammar.STATEMENTS.stream().map(Statement::keyword).toList());
        return nearest != null ? "did you mean '" + nearest + "'?" : "a statement starts with " + Grammar.keywordList();
    }

    /** Every word of the table, with the keywords it suggests: for the test that holds docs/errors.md to it. */
    static Map<String, List<String>> synonyms() {
        return Map.copyOf(SYNONYMS);
    }

    /** Makes each of {@code words} (separated by blanks) mean {@code keywords}. */
    private static void synonyms(String words, String... keywords) {
        for (String word : words.split(" ")) {
            SYNONYMS.put(word, List.of(keywords));
        }
    }

    /**
     * The candidate nearest to {@code word} (the first in alphabetical order of equally near
     * ones), or null if none is near enough: within two edits, or a third of the candidate's
     * length for long words. Case is ignored, so that {@code IOR} finds {@code ior}.
     */
    static String nearest(String word, Collection<String> candidates) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String candidate : candidates.stream().sorted().toList()) {
            int distance = editDistance(word.toLowerCase(Locale.ROOT), candidate.toLowerCase(Locale.ROOT));
            if (distance < bestDistance) {
                bestDistance = distance;
                best = candidate;
            }
        }
        return best != null && bestDistance <= Math.max(2, best.length() / 3) ? best : null;
    }

    /** The Levenshtein distance: the fewest single-character edits that turn a into b. */
    static int editDistance(String a, String b) {
        int[] previous = new int[b.length() + 1];
        int[] current = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int substitution = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(substitution, Math.min(previous[j], current[j - 1]) + 1);
            }
            int[] swap = previous;
            previous = current;
            current = swap;
        }
        return previous[b.length()];
    }
}
